//! `durer watch`: renders again when the scene, an include, a data file or an image map
//! changes; an error keeps the last good image; a render in progress is abandoned; the
//! `--serve` page in headless Chromium shows the new image and then the diagnostic.

use crate::farm::{free_port, have_or_install};
use std::io::{BufRead, BufReader};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// A running `durer watch` whose standard error lines are collected.
struct Watching {
    child: Child,
    lines: Arc<Mutex<Vec<String>>>,
}

impl Watching {
    fn start(dir: &Path, args: &[&str]) -> Watching {
        let mut child = Command::new(env!("CARGO_BIN_EXE_durer"))
            .arg("watch")
            .args(args)
            .current_dir(dir)
            .stderr(Stdio::piped())
            .stdout(Stdio::null())
            .spawn()
            .expect("start durer watch");
        let lines = Arc::new(Mutex::new(Vec::new()));
        let stderr = child.stderr.take().expect("stderr");
        let sink = lines.clone();
        std::thread::spawn(move || {
            for line in BufReader::new(stderr).lines().map_while(Result::ok) {
                sink.lock().unwrap().push(line);
            }
        });
        Watching { child, lines }
    }

    fn count(&self, text: &str) -> usize {
        self.lines
            .lock()
            .unwrap()
            .iter()
            .filter(|l| l.contains(text))
            .count()
    }

    /// Waits until `count` lines contain `text` (30 s at most).
    fn wait_for(&self, text: &str, count: usize) {
        let start = Instant::now();
        while self.count(text) < count {
            assert!(
                start.elapsed() < Duration::from_secs(30),
                "no {count} lines with {text:?} after 30 s:\n{}",
                self.lines.lock().unwrap().join("\n")
            );
            std::thread::sleep(Duration::from_millis(20));
        }
    }

    /// Ctrl-C: the watch stops with exit code 0.
    fn stop(mut self) {
        let pid = self.child.id().to_string();
        let _ = Command::new("kill").args(["-INT", &pid]).status();
        let start = Instant::now();
        loop {
            if let Ok(Some(status)) = self.child.try_wait() {
                assert_eq!(status.code(), Some(0), "durer watch after Ctrl-C");
                break;
            }
            assert!(
                start.elapsed() < Duration::from_secs(10),
                "watch ignores Ctrl-C"
            );
            std::thread::sleep(Duration::from_millis(20));
        }
        self.wait_for("stopped watching", 1);
    }
}

impl Drop for Watching {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// Replaces a file the way editors save: a new file renamed over the old.
fn save(path: &Path, text: &[u8]) {
    let temporary = path.with_extension("saving");
    std::fs::write(&temporary, text).unwrap();
    std::fs::rename(&temporary, path).unwrap();
}

fn centre(path: &Path) -> [u8; 3] {
    let image = image::open(path)
        .expect("decode the watch's image")
        .to_rgb8();
    image.get_pixel(image.width() / 2, image.height() / 2).0
}

const SCENE: &str = "#version 3.7;\n#include \"colour.inc\"\n\
    #fopen Data \"radius.txt\" read\n#read (Data, R)\n#fclose Data\n\
    camera { location <0, 0, -4> look_at 0 }\nlight_source { <0, 0, -10> rgb 1 }\n\
    sphere { 0, R pigment { Col } finish { ambient 1 diffuse 0 } }\n";

fn scene_folder(name: &str) -> PathBuf {
    let dir = crate::scratch(name);
    std::fs::write(dir.join("scene.pov"), SCENE).unwrap();
    std::fs::write(dir.join("colour.inc"), "#declare Col = rgb <1, 0.5, 0>;\n").unwrap();
    std::fs::write(dir.join("radius.txt"), "1,\n").unwrap();
    dir
}

#[test]
fn renders_again_when_the_scene_an_include_or_a_data_file_changes() {
    let dir = scene_folder("watch-files");
    let out = dir.join("out.png");
    let watch = Watching::start(
        &dir,
        &[
            "scene.pov",
            "--width",
            "40",
            "--height",
            "30",
            "-o",
            "out.png",
        ],
    );
    watch.wait_for("full 40x30", 1);
    assert_eq!(centre(&out), [255, 188, 0], "orange (0.5 in sRGB is 188)");
    // The include.
    save(&dir.join("colour.inc"), b"#declare Col = rgb <0, 0, 1>;\n");
    watch.wait_for("full 40x30", 2);
    assert_eq!(centre(&out), [0, 0, 255]);
    // The data file read by #read: a radius too small to reach the centre pixel's ray?
    // No: the sphere still covers the centre; a tiny one leaves the background.
    save(&dir.join("radius.txt"), b"0.01,\n");
    watch.wait_for("full 40x30", 3);
    assert_eq!(centre(&out), [0, 0, 0], "the sphere shrank to a dot");
    // The scene itself, saved with an error: the diagnostic, and the image is kept.
    let before = std::fs::read(&out).unwrap();
    save(
        &dir.join("scene.pov"),
        SCENE.replace("sphere { 0, R", "sphere { 0, ").as_bytes(),
    );
    watch.wait_for("the last good image is kept", 1);
    assert_eq!(
        watch.count("expected a float, found a pigment"),
        1,
        "the diagnostic is printed: {:?}",
        watch.lines.lock().unwrap()
    );
    assert_eq!(
        std::fs::read(&out).unwrap(),
        before,
        "the last good image is kept"
    );
    // Fixed again (and bigger): a new image.
    save(
        &dir.join("scene.pov"),
        SCENE.replace("sphere { 0, R", "sphere { 0, 2").as_bytes(),
    );
    watch.wait_for("full 40x30", 4);
    assert_eq!(centre(&out), [0, 0, 255]);
    // The quick preview came before every full image.
    assert_eq!(watch.count("preview 10x8"), 4);
    watch.stop();
}

#[test]
fn an_image_map_change_renders_again() {
    let dir = crate::scratch("watch-image-map");
    let texture = |colour: [u8; 3]| {
        image::RgbImage::from_pixel(4, 4, image::Rgb(colour))
            .save(dir.join("texture.png"))
            .unwrap();
    };
    texture([255, 0, 0]);
    std::fs::write(
        dir.join("scene.pov"),
        "camera { orthographic location <0.5, 0.5, -1> look_at <0.5, 0.5, 0> right x up y }\n\
         plane { z, 0 pigment { image_map { png \"texture.png\" } } finish { ambient 1 diffuse 0 } }\n",
    )
    .unwrap();
    let watch = Watching::start(
        &dir,
        &[
            "scene.pov",
            "--width",
            "16",
            "--height",
            "16",
            "-o",
            "out.png",
        ],
    );
    watch.wait_for("full 16x16", 1);
    assert_eq!(centre(&dir.join("out.png")), [255, 0, 0]);
    // A new file renamed over the old (as image editors save).
    let temporary = dir.join("new.png");
    image::RgbImage::from_pixel(4, 4, image::Rgb([0, 255, 0]))
        .save(&temporary)
        .unwrap();
    std::fs::rename(&temporary, dir.join("texture.png")).unwrap();
    watch.wait_for("full 16x16", 2);
    assert_eq!(centre(&dir.join("out.png")), [0, 255, 0]);
    watch.stop();
}

#[test]
fn a_render_in_progress_is_abandoned_when_a_file_changes() {
    let dir = scene_folder("watch-abandon");
    // Slow enough (focal blur, one thread) that the change lands during the full render.
    let slow = SCENE.replace(
        "look_at 0 }",
        "look_at 0 aperture 0.5 blur_samples 400 focal_point <0, 0, 3> }",
    );
    std::fs::write(dir.join("scene.pov"), &slow).unwrap();
    let watch = Watching::start(
        &dir,
        &[
            "scene.pov",
            "--width",
            "320",
            "--height",
            "240",
            "--threads",
            "1",
            "-o",
            "out.png",
        ],
    );
    watch.wait_for("preview 80x60", 1);
    save(&dir.join("scene.pov"), SCENE.as_bytes());
    watch.wait_for("the render was abandoned", 1);
    watch.wait_for("full 320x240", 1);
    assert_eq!(centre(&dir.join("out.png")), [255, 188, 0]);
    watch.stop();
}

/// One headless Chromium page kept open, driven over the DevTools protocol by
/// `browser.py` (a Python script: the protocol needs a pipe at file descriptors 3 and 4).
struct Page {
    child: Child,
    replies: BufReader<std::process::ChildStdout>,
    dir: PathBuf,
}

impl Page {
    fn open(dir: &Path, url: &str) -> Result<Page, String> {
        let mut child = Command::new("python3")
            .arg(Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/integration/browser.py"))
            .arg(url)
            .arg(dir.join("chromium-profile"))
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(std::fs::File::create(dir.join("browser.log")).map_err(|e| e.to_string())?)
            .spawn()
            .map_err(|e| format!("cannot run python3: {e}"))?;
        let stdout = child.stdout.take().ok_or("no stdout")?;
        let mut page = Page {
            child,
            replies: BufReader::new(stdout),
            dir: dir.to_path_buf(),
        };
        match page.reply().as_deref() {
            Some("ready") => Ok(page),
            other => Err(format!("the page did not load: {other:?}")),
        }
    }

    fn reply(&mut self) -> Option<String> {
        let mut line = String::new();
        self.replies.read_line(&mut line).ok()?;
        (!line.is_empty()).then(|| line.trim_end().to_string())
    }

    fn send(&mut self, command: &str) -> String {
        use std::io::Write;
        let stdin = self.child.stdin.as_mut().expect("stdin");
        writeln!(stdin, "{command}").expect("write to browser.py");
        stdin.flush().expect("flush");
        self.reply().unwrap_or_else(|| {
            panic!(
                "no reply from browser.py to {command:?}: {}",
                std::fs::read_to_string(self.dir.join("browser.log")).unwrap_or_default()
            )
        })
    }

    /// The text of an element of the page.
    fn text(&mut self, id: &str) -> String {
        let value = self.send(&format!("eval document.getElementById('{id}').innerText"));
        serde_json::from_str::<String>(&value).unwrap_or(value)
    }

    fn screenshot(&mut self) -> image::RgbImage {
        let path = self.dir.join("shot.png");
        assert_eq!(self.send(&format!("shot {}", path.display())), "ok");
        image::open(&path).expect("decode the screenshot").to_rgb8()
    }

    /// Screenshots until `ready` holds for one (10 s at most).
    fn screenshot_when(
        &mut self,
        what: &str,
        ready: impl Fn(&image::RgbImage) -> bool,
    ) -> image::RgbImage {
        let start = Instant::now();
        loop {
            let shot = self.screenshot();
            if ready(&shot) {
                return shot;
            }
            assert!(
                start.elapsed() < Duration::from_secs(10),
                "the page never showed {what}"
            );
            std::thread::sleep(Duration::from_millis(100));
        }
    }
}

impl Drop for Page {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

fn pixels_like(image: &image::RgbImage, colour: [u8; 3]) -> usize {
    image
        .pixels()
        .filter(|p| p.0.iter().zip(colour).all(|(a, b)| a.abs_diff(b) <= 8))
        .count()
}

#[test]
fn the_preview_page_in_headless_chromium_shows_the_new_image_then_the_diagnostic() {
    if !have_or_install("chromium", "chromium") {
        println!("skipped: Chromium is not installed and apt-get install chromium failed");
        return;
    }
    let dir = scene_folder("watch-browser");
    let port = free_port();
    let address = format!("127.0.0.1:{port}");
    let watch = Watching::start(
        &dir,
        &[
            "scene.pov",
            "--width",
            "160",
            "--height",
            "120",
            "--serve",
            &address,
        ],
    );
    watch.wait_for("full 160x120", 1);
    let url = format!("http://{address}/");
    // One page, opened once: everything after this arrives without reloading.
    let mut page = match Page::open(&dir, &url) {
        Ok(page) => page,
        Err(message) => panic!("headless Chromium: {message}"),
    };
    let first = page.screenshot_when("the orange sphere", |shot| {
        pixels_like(shot, [255, 188, 0]) > 2000
    });
    assert!(
        page.text("pass").contains("full image, 160×120"),
        "{}",
        page.text("pass")
    );
    assert!(
        page.text("stats").contains("camera rays"),
        "the statistics show"
    );
    drop(first);
    // Edit the include: the open page shows the blue sphere.
    save(&dir.join("colour.inc"), b"#declare Col = rgb <0, 0, 1>;\n");
    let second = page.screenshot_when("the new image", |shot| {
        pixels_like(shot, [0, 0, 255]) > 2000
    });
    assert_eq!(
        pixels_like(&second, [255, 188, 0]),
        0,
        "and not the old one"
    );
    // An error: the page shows the diagnostic with its source line and keeps the image.
    save(
        &dir.join("scene.pov"),
        SCENE.replace("sphere { 0, R", "sphere { 0, ").as_bytes(),
    );
    let third = page.screenshot_when("the diagnostic", |shot| {
        pixels_like(shot, [0xee, 0x55, 0x55]) > 50
    });
    assert!(
        pixels_like(&third, [0, 0, 255]) > 2000,
        "the last good image stays"
    );
    let diagnostics = page.text("diagnostics");
    assert!(
        diagnostics.contains("expected a float, found a pigment")
            && diagnostics.contains("sphere { 0,  pigment { Col }"),
        "the page holds the diagnostic with its source line:\n{diagnostics}"
    );
    assert!(page.text("status").contains("the last good image is kept"));
    // Fixed: the new image replaces the diagnostic.
    save(
        &dir.join("scene.pov"),
        SCENE
            .replace("pigment { Col }", "pigment { rgb <0, 1, 0> }")
            .as_bytes(),
    );
    let fourth = page.screenshot_when("the fixed scene", |shot| {
        pixels_like(shot, [0, 255, 0]) > 2000
    });
    assert_eq!(
        pixels_like(&fourth, [0xee, 0x55, 0x55]),
        0,
        "and no diagnostic"
    );
    drop(page);
    watch.stop();
}
