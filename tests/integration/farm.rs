//! Split renders: `--tile I/N` + `durer merge` equal a whole render byte for byte; refused
//! merges; the repo's GNU parallel recipe run for real.

use std::path::{Path, PathBuf};
use std::process::Command;

fn durer() -> Command {
    Command::new(env!("CARGO_BIN_EXE_durer"))
}

const SCENE: &str = "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n\
    camera { location <0, 1, -4> look_at 0 aperture 0.3 blur_samples 4 focal_point <0,0,0> }\n\
    light_source { <5, 5, -5> rgb 1 }\nplane { y, -1 pigment { checker rgb 0 rgb 1 } }\n\
    sphere { 0, 1 pigment { rgb <1, 0.5, 0.2> } finish { phong 0.5 } }\n";

fn run(command: &mut Command) {
    let out = command.output().expect("run durer");
    assert!(
        out.status.success(),
        "{:?} failed: {}",
        command,
        String::from_utf8_lossy(&out.stderr)
    );
}

/// Renders `scene` whole to `out` and as `count` tiles merged to `merged`, and checks
/// that the two files are the same bytes.
fn whole_and_tiles(dir: &Path, scene: &Path, count: u32, extra: &[&str], out: &str) {
    // One frame of an animation: files get its number.
    let frame = extra
        .iter()
        .position(|a| *a == "--frame")
        .map_or("", |i| extra[i + 1]);
    run(durer()
        .arg("render")
        .arg(scene)
        .args(["--width", "64", "--height", "48", "-q", "-o"])
        .arg(dir.join(format!("whole.{out}")))
        .args(extra));
    let mut tiles = Vec::new();
    for index in 0..count {
        let tile = dir.join(format!("t{index}"));
        run(durer()
            .arg("render")
            .arg(scene)
            .args(["--width", "64", "--height", "48", "-q", "--tile"])
            .arg(format!("{index}/{count}"))
            .arg("-o")
            .arg(&tile)
            .args(extra));
        tiles.push(dir.join(format!("t{index}{frame}.tile.png")));
    }
    run(durer()
        .arg("merge")
        .arg(dir.join(format!("merged.{out}")))
        .args(&tiles));
    let whole = std::fs::read(dir.join(format!("whole{frame}.{out}"))).unwrap();
    let merged = std::fs::read(dir.join(format!("merged.{out}"))).unwrap();
    assert!(
        whole == merged,
        "{extra:?} .{out}: merged tiles differ from the whole render"
    );
}

fn write(dir: &Path, name: &str, text: &str) -> PathBuf {
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path
}

const PLAIN: &str = "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n\
    camera { location <0, 1, -4> look_at 0 }\n\
    light_source { <5, 5, -5> rgb 1 }\nplane { y, -1 pigment { checker rgb 0 rgb 1 } }\n\
    sphere { 0, 1 pigment { rgb <1, 0.5, 0.2> } finish { phong 0.5 } }\n";

#[test]
fn tiles_merge_to_the_whole_render_for_every_option_family() {
    let dir = crate::scratch("farm-tiles");
    let plain = write(&dir, "plain.pov", PLAIN);
    let blur = write(&dir, "blur.pov", SCENE);
    whole_and_tiles(&dir, &plain, 16, &["+A0.1", "+AM1", "+J"], "png");
    whole_and_tiles(&dir, &plain, 6, &["+A0.1", "+AM2", "+R3"], "exr");
    whole_and_tiles(&dir, &plain, 5, &["+A0.1", "+UA"], "tga");
    whole_and_tiles(&dir, &plain, 3, &["+A0.1", "+UA", "+FC"], "tga");
    whole_and_tiles(&dir, &plain, 7, &["+A0.2", "+FN16"], "png");
    whole_and_tiles(&dir, &plain, 4, &["+A0.2"], "bmp");
    whole_and_tiles(&dir, &plain, 4, &["+A0.2"], "hdr");
    whole_and_tiles(&dir, &blur, 4, &[], "jpg");
    let radiosity = write(
        &dir,
        "radiosity.pov",
        &PLAIN.replace(
            "global_settings { assumed_gamma 1.0 }",
            "global_settings { assumed_gamma 1.0 radiosity { count 20 } }",
        ),
    );
    whole_and_tiles(&dir, &radiosity, 4, &["+A0.3"], "ppm");
    whole_and_tiles(&dir, &radiosity, 16, &[], "png");
    let photons_and_media = write(
        &dir,
        "photons.pov",
        &PLAIN
            .replace(
                "global_settings { assumed_gamma 1.0 }",
                "global_settings { assumed_gamma 1.0 photons { count 3000 } }",
            )
            .replace(
                "sphere { 0, 1 pigment { rgb <1, 0.5, 0.2> } finish { phong 0.5 } }",
                "sphere { 0, 1 pigment { rgbf 1 } interior { ior 1.5 } \
                 photons { target refraction on reflection on } }\n\
                 box { <-3, -1, 1>, <3, 2, 2> hollow pigment { rgbt 1 } \
                 interior { media { scattering { 1, 0.3 } intervals 2 samples 2, 4 } } }",
            ),
    );
    whole_and_tiles(&dir, &photons_and_media, 9, &["+A0.3"], "png");
    // A frame of an animation: its clock reaches the tiles.
    let animated = write(
        &dir,
        "animated.pov",
        &PLAIN.replace("look_at 0", "look_at <clock, 0, 0>"),
    );
    whole_and_tiles(&dir, &animated, 4, &["+KFF5", "--frame", "3"], "png");
}

#[test]
fn a_tile_is_a_png_of_its_pixels_saying_which_tile_it_is() {
    let dir = crate::scratch("farm-tile-file");
    let scene = write(&dir, "s.pov", PLAIN);
    run(durer()
        .arg("render")
        .arg(&scene)
        .args(["--width", "64", "--height", "48", "-q", "--tile", "5/16"]));
    // Without -o the tile is named after the scene and the split.
    let path = dir.join("s-5of16.tile.png");
    let decoded = image::open(&path).expect("a tile decodes as a PNG");
    assert_eq!((decoded.width(), decoded.height()), (16, 12));
    let bytes = std::fs::read(&path).unwrap();
    let text = String::from_utf8_lossy(&bytes);
    for field in [
        "durer-tile",
        "size 64 48",
        "tile 5 16",
        "region 16 12 32 24",
        "fingerprint ",
    ] {
        assert!(text.contains(field), "tile metadata lacks {field:?}");
    }
}

#[test]
fn merges_refused_for_bad_sets() {
    let dir = crate::scratch("farm-refused");
    let scene = write(&dir, "s.pov", SCENE);
    for (name, extra) in [("a", "+A0.3"), ("b", "-A")] {
        for index in 0..2 {
            run(durer()
                .arg("render")
                .arg(&scene)
                .args(["--width", "16", "--height", "12", "-q", "--tile"])
                .arg(format!("{index}/2"))
                .arg("-o")
                .arg(dir.join(format!("{name}{index}")))
                .arg(extra));
        }
    }
    let merge = |tiles: &[&str]| {
        let out = durer()
            .arg("merge")
            .arg(dir.join("out.png"))
            .args(tiles.iter().map(|t| dir.join(t)))
            .output()
            .unwrap();
        (
            out.status.code(),
            String::from_utf8_lossy(&out.stderr).into_owned(),
        )
    };
    let refused = |tiles: &[&str], message: &str| {
        let (code, text) = merge(tiles);
        assert_eq!(code, Some(2), "{tiles:?}: {text}");
        assert!(text.contains(message), "{tiles:?}: {text}");
        assert!(!dir.join("out.png").exists(), "{tiles:?} wrote an image");
    };
    refused(&["a0.tile.png"], "tiles missing from the set of 2: 1");
    refused(&["a0.tile.png", "b1.tile.png"], "different renders");
    refused(&["a0.tile.png", "a0.tile.png"], "are both tile 0");
    std::fs::write(dir.join("junk.tile.png"), b"hello").unwrap();
    refused(&["junk.tile.png", "a1.tile.png"], "not a PNG file");
    let whole = std::fs::read(dir.join("a1.tile.png")).unwrap();
    std::fs::write(dir.join("cut.tile.png"), &whole[..whole.len() - 40]).unwrap();
    refused(&["a0.tile.png", "cut.tile.png"], "truncated");
    let mut damaged = whole.clone();
    let middle = damaged.len() / 2;
    damaged[middle] ^= 1;
    std::fs::write(dir.join("damaged.tile.png"), &damaged).unwrap();
    refused(&["a0.tile.png", "damaged.tile.png"], "damaged");
    run(durer()
        .arg("render")
        .arg(&scene)
        .args(["--width", "16", "--height", "12", "-q", "-o"])
        .arg(dir.join("plain.png")));
    refused(&["a0.tile.png", "plain.png"], "not a durer tile");
    assert_eq!(merge(&["a1.tile.png", "a0.tile.png"]).0, Some(0));
}

/// Whether `program` runs, installing `package` with apt-get when it does not.
pub fn have_or_install(program: &str, package: &str) -> bool {
    let found = |p: &str| {
        Command::new("sh")
            .args(["-c", &format!("command -v {p} || test -x /usr/sbin/{p}")])
            .output()
            .is_ok_and(|o| o.status.success())
    };
    if found(program) {
        return true;
    }
    let _ = Command::new("apt-get")
        .args(["install", "-y", package])
        .output();
    found(program)
}

#[test]
fn gnu_parallel_recipe() {
    if !have_or_install("parallel", "parallel") {
        println!("skipped: GNU parallel is not installed and apt-get install parallel failed");
        return;
    }
    let dir = crate::scratch("farm-parallel");
    let scene = dir.join("s.pov");
    std::fs::write(
        &scene,
        SCENE.replace("aperture 0.3 blur_samples 4 focal_point <0,0,0>", ""),
    )
    .unwrap();
    let recipe = Path::new(env!("CARGO_MANIFEST_DIR")).join("farm/parallel.sh");
    let out = Command::new("sh")
        .arg(recipe)
        .arg(&scene)
        .arg("16")
        .arg(dir.join("tiles"))
        .arg(dir.join("merged.png"))
        .args(["-j", "2", "--", "--width", "64", "--height", "48", "+A0.3"])
        .env("DURER", env!("CARGO_BIN_EXE_durer"))
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    run(durer()
        .arg("render")
        .arg(&scene)
        .args(["--width", "64", "--height", "48", "+A0.3", "-q", "-o"])
        .arg(dir.join("whole.png")));
    assert!(
        std::fs::read(dir.join("whole.png")).unwrap()
            == std::fs::read(dir.join("merged.png")).unwrap(),
        "GNU parallel's merged tiles differ from the whole render"
    );
}

fn repo(path: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(path)
}

/// The example scene the scheduler tests split (16 tiles, anti-aliased).
const FARM_OPTIONS: [&str; 5] = ["--width", "160", "--height", "120", "+A0.3"];

/// Renders the showcase example whole, for comparison with a scheduler's merged tiles.
fn whole_showcase(dir: &Path) -> Vec<u8> {
    let whole = dir.join("whole.png");
    run(durer()
        .arg("render")
        .arg(repo("examples/showcase.pov"))
        .args(FARM_OPTIONS)
        .arg("-q")
        .arg("-o")
        .arg(&whole));
    std::fs::read(whole).unwrap()
}

/// A single-node Slurm cluster on localhost (`slurmctld` and `slurmd`, `auth/none`),
/// its configuration and state in `dir`; stopped when dropped.
struct SlurmCluster {
    dir: PathBuf,
    conf: PathBuf,
}

/// A free port on 127.0.0.1.
pub fn free_port() -> u16 {
    std::net::TcpListener::bind("127.0.0.1:0")
        .and_then(|l| l.local_addr())
        .map(|a| a.port())
        .expect("a free port")
}

impl SlurmCluster {
    fn start(dir: &Path) -> Result<SlurmCluster, String> {
        let host = std::fs::read_to_string("/proc/sys/kernel/hostname")
            .map_err(|e| e.to_string())?
            .trim()
            .to_string();
        let cpus = std::thread::available_parallelism().map_or(1, |n| n.get());
        for sub in ["state", "spool"] {
            std::fs::create_dir_all(dir.join(sub)).map_err(|e| e.to_string())?;
        }
        let d = dir.display();
        let conf = dir.join("slurm.conf");
        let text = format!(
            "ClusterName=durertest\nSlurmctldHost={host}(127.0.0.1)\n\
             SlurmctldPort={}\nSlurmdPort={}\nAuthType=auth/none\nCredType=cred/none\n\
             SlurmUser=root\nSlurmdUser=root\nStateSaveLocation={d}/state\n\
             SlurmdSpoolDir={d}/spool\nSlurmctldPidFile={d}/slurmctld.pid\n\
             SlurmdPidFile={d}/slurmd.pid\nSlurmctldLogFile={d}/slurmctld.log\n\
             SlurmdLogFile={d}/slurmd.log\nProctrackType=proctrack/linuxproc\n\
             TaskPlugin=task/none\nSchedulerType=sched/builtin\nSelectType=select/cons_tres\n\
             SelectTypeParameters=CR_Core\nMpiDefault=none\nReturnToService=2\n\
             JobAcctGatherType=jobacct_gather/none\nAccountingStorageType=accounting_storage/none\n\
             NodeName={host} NodeAddr=127.0.0.1 CPUs={cpus} State=UNKNOWN\n\
             PartitionName=test Nodes=ALL Default=YES MaxTime=INFINITE State=UP\n",
            free_port(),
            free_port(),
        );
        std::fs::write(&conf, text).map_err(|e| e.to_string())?;
        let cluster = SlurmCluster {
            dir: dir.to_path_buf(),
            conf,
        };
        for daemon in ["slurmctld", "slurmd"] {
            let status = Command::new(daemon)
                .arg("-f")
                .arg(&cluster.conf)
                .status()
                .map_err(|e| format!("{daemon}: {e}"))?;
            if !status.success() {
                return Err(format!("{daemon} did not start: {}", cluster.logs()));
            }
        }
        let start = std::time::Instant::now();
        loop {
            let state = cluster.command("sinfo").args(["-h", "-o", "%T"]).output();
            if state.is_ok_and(|o| String::from_utf8_lossy(&o.stdout).trim() == "idle") {
                return Ok(cluster);
            }
            if start.elapsed().as_secs() > 60 {
                return Err(format!(
                    "the node is not idle after 60 s: {}",
                    cluster.logs()
                ));
            }
            std::thread::sleep(std::time::Duration::from_millis(200));
        }
    }

    /// A Slurm command (or any) with this cluster's configuration.
    fn command(&self, program: &str) -> Command {
        let mut command = Command::new(program);
        command.env("SLURM_CONF", &self.conf);
        command
    }

    fn logs(&self) -> String {
        let mut text = String::new();
        for log in ["slurmctld.log", "slurmd.log"] {
            let body = std::fs::read_to_string(self.dir.join(log)).unwrap_or_default();
            let tail: Vec<&str> = body.lines().rev().take(15).collect();
            text += &format!("\n--- {log} (last lines)\n");
            for line in tail.iter().rev() {
                text += line;
                text.push('\n');
            }
        }
        text
    }
}

impl Drop for SlurmCluster {
    fn drop(&mut self) {
        let _ = self.command("scontrol").arg("shutdown").output();
        // Whatever did not stop within 5 s is killed.
        for pid_file in ["slurmd.pid", "slurmctld.pid"] {
            let Ok(pid) = std::fs::read_to_string(self.dir.join(pid_file)) else {
                continue;
            };
            let alive = || Path::new(&format!("/proc/{}", pid.trim())).exists();
            for _ in 0..50 {
                if !alive() {
                    break;
                }
                std::thread::sleep(std::time::Duration::from_millis(100));
            }
            if alive() {
                let _ = Command::new("kill").args(["-9", pid.trim()]).status();
            }
        }
    }
}

#[test]
fn slurm_recipe_on_a_single_node_cluster() {
    if !have_or_install("slurmctld", "slurm-wlm") || !have_or_install("sbatch", "slurm-wlm") {
        println!("skipped: Slurm is not installed and apt-get install slurm-wlm failed");
        return;
    }
    let root = Command::new("id")
        .arg("-u")
        .output()
        .is_ok_and(|o| String::from_utf8_lossy(&o.stdout).trim() == "0");
    if !root {
        println!("skipped: the single-node Slurm cluster needs root (slurmd runs jobs as root)");
        return;
    }
    let dir = crate::scratch("farm-slurm");
    let started = std::time::Instant::now();
    let cluster = SlurmCluster::start(&dir).unwrap_or_else(|e| panic!("Slurm: {e}"));
    let up = started.elapsed();
    let merged = dir.join("merged.png");
    let submitted = cluster
        .command("sh")
        .arg(repo("farm/slurm-submit.sh"))
        .arg(repo("examples/showcase.pov"))
        .arg("16")
        .arg(dir.join("tiles"))
        .arg(&merged)
        .args(FARM_OPTIONS)
        .env("DURER", env!("CARGO_BIN_EXE_durer"))
        .current_dir(&dir)
        .output()
        .unwrap();
    assert!(
        submitted.status.success(),
        "slurm-submit.sh: {}{}",
        String::from_utf8_lossy(&submitted.stderr),
        cluster.logs()
    );
    // Four frames of an animation of the same scene, one array task each.
    let frames = cluster
        .command("sbatch")
        .args(["--parsable", "--array=1-4"])
        .arg(repo("farm/slurm-frames.sbatch"))
        .arg(repo("examples/showcase.pov"))
        .arg(dir.join("frames"))
        .args(["+KFF4", "--width", "32", "--height", "24"])
        .env("DURER", env!("CARGO_BIN_EXE_durer"))
        .current_dir(&dir)
        .output()
        .unwrap();
    assert!(
        frames.status.success(),
        "{}",
        String::from_utf8_lossy(&frames.stderr)
    );
    // Wait until the queue is empty (the merge job is the last to leave it).
    loop {
        let queue = cluster
            .command("squeue")
            .args(["-h", "-o", "%i %T"])
            .output();
        let queue = queue.map(|o| String::from_utf8_lossy(&o.stdout).into_owned());
        if queue.as_deref().is_ok_and(|q| q.trim().is_empty()) {
            break;
        }
        assert!(
            started.elapsed().as_secs() < 300,
            "Slurm jobs still queued after 300 s: {queue:?}{}",
            cluster.logs()
        );
        std::thread::sleep(std::time::Duration::from_millis(250));
    }
    let done = started.elapsed();
    let job_logs = || {
        let mut text = String::new();
        for entry in std::fs::read_dir(&dir).unwrap().flatten() {
            if entry.path().extension().is_some_and(|e| e == "log")
                && entry.file_name().to_string_lossy().starts_with("durer-")
            {
                text += &format!(
                    "\n--- {}\n{}",
                    entry.file_name().to_string_lossy(),
                    std::fs::read_to_string(entry.path()).unwrap_or_default()
                );
            }
        }
        text
    };
    let merged = std::fs::read(&merged)
        .unwrap_or_else(|e| panic!("no merged image ({e}): {}{}", job_logs(), cluster.logs()));
    let tiles = std::fs::read_dir(dir.join("tiles")).unwrap().count();
    assert_eq!(tiles, 16, "{}", job_logs());
    assert!(
        merged == whole_showcase(&dir),
        "Slurm's merged tiles differ from the whole render"
    );
    std::fs::create_dir_all(dir.join("local")).unwrap();
    run(durer()
        .arg("render")
        .arg(repo("examples/showcase.pov"))
        .args(["+KFF4", "--width", "32", "--height", "24", "-q", "-o"])
        .arg(dir.join("local/")));
    for frame in 1..=4 {
        let name = format!("showcase{frame}.png");
        let slurm = std::fs::read(dir.join("frames").join(&name))
            .unwrap_or_else(|e| panic!("frame {name} ({e}): {}", job_logs()));
        assert!(
            slurm == std::fs::read(dir.join("local").join(&name)).unwrap(),
            "Slurm's frame {frame} differs from the same frame rendered locally"
        );
    }
    println!(
        "Slurm: cluster up in {:.1} s, 16 tiles rendered and merged and 4 frames in {:.1} s",
        up.as_secs_f64(),
        (done - up).as_secs_f64()
    );
}

/// The Kubernetes recipe's pods, run as Kubernetes would run them (no cluster here): each
/// index's container command in the volume's folder with `JOB_COMPLETION_INDEX` set, then
/// the merge Job's command. The manifests are read with Python's YAML parser.
#[test]
fn kubernetes_manifests_run_as_their_pods_would() {
    let dir = crate::scratch("farm-k8s");
    let script = "import json, sys, yaml\n\
        job = yaml.safe_load(open(sys.argv[1]))\n\
        merge = yaml.safe_load(open(sys.argv[2]))\n\
        tile = job['spec']['template']['spec']['containers'][0]\n\
        m = merge['spec']['template']['spec']['containers'][0]\n\
        print(json.dumps([job['spec']['completionMode'], job['spec']['completions'],\n\
            tile['command'] + tile.get('args', []), m['command'] + m.get('args', [])]))\n";
    let parsed = Command::new("python3")
        .args(["-c", script])
        .arg(repo("farm/k8s-indexed-job.yaml"))
        .arg(repo("farm/k8s-merge-job.yaml"))
        .output();
    let parsed = match parsed {
        Ok(out) if out.status.success() => out.stdout,
        Ok(out) => {
            println!(
                "skipped: Python cannot read the manifests (PyYAML?): {}",
                String::from_utf8_lossy(&out.stderr)
            );
            return;
        }
        Err(e) => {
            println!("skipped: python3 is not available ({e})");
            return;
        }
    };
    let parsed: serde_json::Value = serde_json::from_slice(&parsed).unwrap();
    assert_eq!(parsed[0], "Indexed");
    let completions = parsed[1].as_u64().unwrap();
    let argv = |k: usize| -> Vec<String> {
        parsed[k]
            .as_array()
            .unwrap()
            .iter()
            .map(|v| v.as_str().unwrap().to_string())
            .collect()
    };
    // The volume holds the scene (the example, and its name in the manifest).
    std::fs::copy(repo("examples/showcase.pov"), dir.join("scene.pov")).unwrap();
    let bin = Path::new(env!("CARGO_BIN_EXE_durer")).parent().unwrap();
    let path = format!(
        "{}:{}",
        bin.display(),
        std::env::var("PATH").unwrap_or_default()
    );
    let pod = |command: &[String], index: Option<u64>| {
        let mut pod = Command::new(&command[0]);
        pod.args(&command[1..]).current_dir(&dir).env("PATH", &path);
        if let Some(index) = index {
            pod.env("JOB_COMPLETION_INDEX", index.to_string());
        }
        let out = pod.output().unwrap();
        assert!(
            out.status.success(),
            "pod {index:?}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
    };
    for index in 0..completions {
        pod(&argv(2), Some(index));
    }
    pod(&argv(3), None);
    let merged = std::fs::read(dir.join("image.png")).unwrap();
    let whole = dir.join("whole.png");
    // The whole render gets the options the manifest gives between the scene and --tile.
    let manifest_options = argv(2).join(" ");
    let extra: Vec<&str> = manifest_options
        .split_whitespace()
        .skip_while(|w| *w != "scene.pov")
        .skip(1)
        .take_while(|w| !w.starts_with("--tile"))
        .collect();
    run(durer()
        .arg("render")
        .arg(dir.join("scene.pov"))
        .args(&extra)
        .arg("-q")
        .arg("-o")
        .arg(&whole));
    assert!(
        merged == std::fs::read(&whole).unwrap(),
        "the Kubernetes pods' merged tiles differ from the whole render ({extra:?})"
    );
}
