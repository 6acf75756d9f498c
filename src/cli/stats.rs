//! Render statistics, as POV-Ray's `+GS` prints them: objects, lights, rays by kind,
//! intersection tests, time per phase, peak memory; as text or JSON (`--stats json`).

use durer::accel::counters::{self, Counter, Counts};
use std::fmt::Write as _;
use std::time::Duration;

/// Statistics of a run, summed over its frames.
#[derive(Clone, Debug, Default)]
pub struct Summary {
    pub frames: usize,
    /// Render threads (for rays per second per thread).
    pub threads: usize,
    /// Objects and lights of the last frame.
    pub objects: usize,
    pub lights: usize,
    pub counts: Counts,
    pub parse: Duration,
    pub build: Duration,
    pub render: Duration,
    pub write: Duration,
    pub total: Duration,
    /// The last frame's parse and render time, for its progress line.
    pub last_parse: Duration,
    pub last_render: Duration,
}

/// Clears the counters of every thread of `pool` (before a frame).
pub fn reset(pool: &rayon::ThreadPool) {
    pool.broadcast(|_| counters::take());
    counters::take();
}

/// The counts of every thread of `pool` (and this one) since [`reset`].
pub fn collect(pool: &rayon::ThreadPool) -> Counts {
    pool.broadcast(|_| counters::take())
        .into_iter()
        .fold(counters::take(), Counts::plus)
}

/// The process's peak resident memory in bytes (Linux: `VmHWM`), if known.
pub fn peak_memory() -> Option<u64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    let kilobytes: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kilobytes * 1024)
}

/// Radiosity samples gathered by bounce, in the order printed, with their names.
const RADIOSITY_SAMPLES: [(Counter, &str, &str); 3] = [
    (
        Counter::RadiositySamplesFirstBounce,
        "first_bounce",
        "first bounce",
    ),
    (
        Counter::RadiositySamplesSecondBounce,
        "second_bounce",
        "second bounce",
    ),
    (Counter::RadiositySamplesDeeper, "deeper", "deeper bounces"),
];

/// The kinds of rays, in the order printed, with their names.
const RAY_KINDS: [(Counter, &str, &str); 6] = [
    (Counter::CameraRays, "camera", "Camera rays"),
    (Counter::ShadowRays, "shadow", "Shadow rays"),
    (Counter::ReflectedRays, "reflected", "Reflected rays"),
    (Counter::RefractedRays, "refracted", "Refracted rays"),
    (Counter::RadiosityRays, "radiosity", "Radiosity rays"),
    (Counter::PhotonRays, "photon", "Photons shot"),
];

impl Summary {
    /// Adds one frame's numbers.
    pub fn add_frame(
        &mut self,
        counts: Counts,
        objects: usize,
        lights: usize,
        parse: Duration,
        build: Duration,
        render: Duration,
    ) {
        self.counts = self.counts.plus(counts);
        self.objects = objects;
        self.lights = lights;
        self.parse += parse;
        self.build += build;
        self.render += render;
        self.last_parse = parse;
        self.last_render = build + render;
    }

    /// The statistics as text, one item per line.
    pub fn text(&self) -> String {
        let mut out = String::new();
        let _ = writeln!(out, "Render statistics");
        let _ = writeln!(out, "  Frames:              {:>14}", self.frames);
        let _ = writeln!(out, "  Objects:             {:>14}", self.objects);
        let _ = writeln!(out, "  Light sources:       {:>14}", self.lights);
        for (counter, _, name) in RAY_KINDS {
            let count = self.counts.get(counter);
            let _ = write!(out, "  {:<21}{:>14}", format!("{name}:"), count);
            match self.rays_per_second_per_thread(count) {
                Some(rate) if count > 0 => {
                    let _ = writeln!(out, "  ({:.3} M/s per thread)", rate / 1e6);
                }
                _ => out.push('\n'),
            }
        }
        if RADIOSITY_SAMPLES
            .iter()
            .any(|(c, _, _)| self.counts.get(*c) > 0)
        {
            let _ = writeln!(out, "  Radiosity samples gathered:");
            for (counter, _, name) in RADIOSITY_SAMPLES {
                let _ = writeln!(
                    out,
                    "    {:<19}{:>14}",
                    format!("{name}:"),
                    self.counts.get(counter)
                );
            }
        }
        let _ = writeln!(
            out,
            "  Intersection tests:  {:>14}",
            self.counts.get(Counter::IntersectionTests)
        );
        for (name, time) in [
            ("Parse time", self.parse),
            ("Bounding time", self.build),
            ("Render time", self.render),
            ("Write time", self.write),
            ("Total time", self.total),
        ] {
            let _ = writeln!(
                out,
                "  {:<21}{:>12.3} s",
                format!("{name}:"),
                time.as_secs_f64()
            );
        }
        if let Some(bytes) = peak_memory() {
            let _ = writeln!(
                out,
                "  Peak memory:         {:>11.1} MiB",
                bytes as f64 / (1024.0 * 1024.0)
            );
        }
        out
    }

    /// `count` rays over the render time and the threads, if both are known.
    fn rays_per_second_per_thread(&self, count: u64) -> Option<f64> {
        let seconds = self.render.as_secs_f64();
        (seconds > 0.0 && self.threads > 0).then(|| count as f64 / seconds / self.threads as f64)
    }

    /// The statistics as one JSON object.
    pub fn json(&self) -> String {
        let object = |entries: &[(Counter, &str, &str)], value: &dyn Fn(Counter) -> String| {
            let items: Vec<String> = entries
                .iter()
                .map(|(counter, key, _)| format!("\"{key}\": {}", value(*counter)))
                .collect();
            items.join(", ")
        };
        let rays = object(&RAY_KINDS, &|counter| self.counts.get(counter).to_string());
        let rates = object(&RAY_KINDS, &|counter| {
            self.rays_per_second_per_thread(self.counts.get(counter))
                .map_or("null".to_string(), |rate| format!("{rate:.0}"))
        });
        let samples = object(&RADIOSITY_SAMPLES, &|counter| {
            self.counts.get(counter).to_string()
        });
        let seconds = |d: Duration| format!("{:.6}", d.as_secs_f64());
        format!(
            "{{\"frames\": {}, \"threads\": {}, \"objects\": {}, \"lights\": {}, \
             \"rays\": {{{rays}}}, \"rays_per_second_per_thread\": {{{rates}}}, \
             \"radiosity_samples\": {{{samples}}}, \"intersection_tests\": {}, \"seconds\": {{\"parse\": {}, \"bounding\": {}, \
             \"render\": {}, \"write\": {}, \"total\": {}}}, \"peak_memory_bytes\": {}}}",
            self.frames,
            self.threads,
            self.objects,
            self.lights,
            self.counts.get(Counter::IntersectionTests),
            seconds(self.parse),
            seconds(self.build),
            seconds(self.render),
            seconds(self.write),
            seconds(self.total),
            peak_memory().map_or("null".to_string(), |b| b.to_string()),
        )
    }
}
