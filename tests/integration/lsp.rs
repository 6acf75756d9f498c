//! `durer lsp` spoken to over stdio, and `--format json|sarif` checked against schemas.

use serde_json::{json, Value};
use std::io::{BufRead, BufReader, Read, Write};
use std::process::{Child, ChildStdin, Command, Stdio};
use std::sync::mpsc;
use std::time::{Duration, Instant};

struct Server {
    child: Child,
    stdin: ChildStdin,
    messages: mpsc::Receiver<Value>,
    next_id: i64,
}

impl Server {
    fn start(budget_ms: u64) -> Server {
        let mut child = Command::new(env!("CARGO_BIN_EXE_durer"))
            .arg("lsp")
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::null())
            .spawn()
            .expect("start durer lsp");
        let stdin = child.stdin.take().expect("stdin");
        let stdout = child.stdout.take().expect("stdout");
        let (send, messages) = mpsc::channel();
        std::thread::spawn(move || {
            let mut reader = BufReader::new(stdout);
            loop {
                let mut length = 0usize;
                loop {
                    let mut line = String::new();
                    if reader.read_line(&mut line).unwrap_or(0) == 0 {
                        return;
                    }
                    let line = line.trim();
                    if line.is_empty() {
                        break;
                    }
                    if let Some(n) = line.strip_prefix("Content-Length: ") {
                        length = n.parse().unwrap_or(0);
                    }
                }
                let mut body = vec![0; length];
                if reader.read_exact(&mut body).is_err() {
                    return;
                }
                if let Ok(value) = serde_json::from_slice::<Value>(&body) {
                    if send.send(value).is_err() {
                        return;
                    }
                }
            }
        });
        let mut server = Server {
            child,
            stdin,
            messages,
            next_id: 1,
        };
        let init = server.request(
            "initialize",
            json!({"processId": null, "rootUri": null, "capabilities": {},
                   "initializationOptions": {"timeBudgetMs": budget_ms}}),
        );
        assert!(
            init["capabilities"]["hoverProvider"]
                .as_bool()
                .unwrap_or(false),
            "{init}"
        );
        server.notify("initialized", json!({}));
        server
    }

    fn send(&mut self, message: Value) {
        let body = message.to_string();
        write!(self.stdin, "Content-Length: {}\r\n\r\n{body}", body.len()).unwrap();
        self.stdin.flush().unwrap();
    }

    fn notify(&mut self, method: &str, params: Value) {
        self.send(json!({"jsonrpc": "2.0", "method": method, "params": params}));
    }

    fn request(&mut self, method: &str, params: Value) -> Value {
        let id = self.next_id;
        self.next_id += 1;
        self.send(json!({"jsonrpc": "2.0", "id": id, "method": method, "params": params}));
        let message = self.wait(|m| m["id"] == json!(id), Duration::from_secs(20));
        message["result"].clone()
    }

    fn wait(&mut self, matches: impl Fn(&Value) -> bool, limit: Duration) -> Value {
        let end = Instant::now() + limit;
        loop {
            let left = end.saturating_duration_since(Instant::now());
            let message = self
                .messages
                .recv_timeout(left)
                .expect("the server answered in time");
            if matches(&message) {
                return message;
            }
        }
    }

    fn diagnostics(&mut self, version: i64) -> Vec<Value> {
        let message = self.wait(
            |m| {
                m["method"] == "textDocument/publishDiagnostics"
                    && m["params"]["version"] == json!(version)
            },
            Duration::from_secs(30),
        );
        message["params"]["diagnostics"]
            .as_array()
            .cloned()
            .unwrap_or_default()
    }

    fn open(&mut self, uri: &str, text: &str) {
        self.notify(
            "textDocument/didOpen",
            json!({"textDocument": {"uri": uri, "languageId": "povray", "version": 1, "text": text}}),
        );
    }

    fn change(&mut self, uri: &str, version: i64, text: &str) {
        self.notify(
            "textDocument/didChange",
            json!({"textDocument": {"uri": uri, "version": version},
                   "contentChanges": [{"text": text}]}),
        );
    }

    fn finish(mut self) {
        let _ = self.request("shutdown", Value::Null);
        self.notify("exit", Value::Null);
        let end = Instant::now() + Duration::from_secs(10);
        loop {
            if let Ok(Some(status)) = self.child.try_wait() {
                assert!(status.success(), "{status}");
                return;
            }
            if Instant::now() > end {
                let _ = self.child.kill();
                panic!("durer lsp did not exit");
            }
            std::thread::sleep(Duration::from_millis(20));
        }
    }
}

fn position(line: u32, character: u32, uri: &str) -> Value {
    json!({"textDocument": {"uri": uri}, "position": {"line": line, "character": character}})
}

#[test]
fn lsp_diagnoses_unsaved_text_and_answers_requests() {
    let dir = crate::scratch("lsp");
    std::fs::write(
        dir.join("part.inc"),
        "#declare Part_Size = 2;\n#declare Broken = 1 + ;\n",
    )
    .unwrap();
    let scene = dir.join("scene.pov");
    let uri = format!("file://{}", scene.display());
    let mut server = Server::start(3000);
    // The file on disk does not exist: the server reads the editor's text.
    server.open(
        &uri,
        "#include \"colors.inc\"\n#declare R = 2;\nsphere { 0, R pigment { color Whte } }\n",
    );
    let first = server.diagnostics(1);
    assert_eq!(first.len(), 1, "{first:?}");
    assert_eq!(
        first[0]["range"]["start"],
        json!({"line": 2, "character": 30})
    );
    let message = first[0]["message"].as_str().unwrap_or("");
    assert!(
        message.contains("Whte") && message.contains("White"),
        "{message}"
    );

    // Fixed text: no diagnostics.
    let fixed = "#include \"colors.inc\"\n#declare R = 2;\n#macro Ball(Size, Colour)\n  sphere { 0, Size pigment { color Colour } }\n#end\nBall(R, White)\n";
    let changed = Instant::now();
    server.change(&uri, 2, fixed);
    assert!(server.diagnostics(2).is_empty());
    eprintln!("change to diagnostics: {:?}", changed.elapsed());

    // Hover: a declared identifier, a standard include's colour, a keyword.
    let hover = server.request("textDocument/hover", position(5, 5, &uri));
    let text = hover["contents"]["value"].as_str().unwrap_or("");
    assert!(
        text.contains("#declare R = 2") && text.contains("line 2"),
        "{text}"
    );
    let hover = server.request("textDocument/hover", position(5, 9, &uri));
    let text = hover["contents"]["value"].as_str().unwrap_or("");
    assert!(text.contains("colors.inc"), "{text}");
    let hover = server.request("textDocument/hover", position(3, 4, &uri));
    let text = hover["contents"]["value"].as_str().unwrap_or("");
    assert!(text.contains("sphere"), "{text}");

    // Definition: a local declaration, and White in the embedded colors.inc.
    let found = server.request("textDocument/definition", position(5, 5, &uri));
    assert_eq!(found["uri"], json!(uri));
    assert_eq!(found["range"]["start"]["line"], json!(1));
    let found = server.request("textDocument/definition", position(5, 10, &uri));
    assert!(
        found["uri"].as_str().unwrap_or("").ends_with("colors.inc"),
        "{found}"
    );

    // Completion inside the macro: its parameters, declared names, colours, keywords.
    let items = server.request("textDocument/completion", position(3, 20, &uri));
    let labels: Vec<&str> = items
        .as_array()
        .map(|a| a.iter().filter_map(|i| i["label"].as_str()).collect())
        .unwrap_or_default();
    for expected in ["Size", "Colour", "R", "Ball", "White", "pigment"] {
        assert!(labels.contains(&expected), "{expected} missing");
    }
    // After `#`: directives only.
    server.change(&uri, 3, "#dec");
    let _ = server.diagnostics(3);
    let items = server.request("textDocument/completion", position(0, 4, &uri));
    let labels: Vec<&str> = items
        .as_array()
        .map(|a| a.iter().filter_map(|i| i["label"].as_str()).collect())
        .unwrap_or_default();
    assert!(
        labels.contains(&"declare") && !labels.contains(&"sphere"),
        "{labels:?}"
    );

    // Document symbols.
    server.change(&uri, 4, fixed);
    let _ = server.diagnostics(4);
    let symbols = server.request(
        "textDocument/documentSymbol",
        json!({"textDocument": {"uri": uri}}),
    );
    let names: Vec<&str> = symbols
        .as_array()
        .map(|a| a.iter().filter_map(|s| s["name"].as_str()).collect())
        .unwrap_or_default();
    assert!(names.starts_with(&["R", "Ball"]), "{names:?}");

    // An error inside an included file is shown at the include line.
    server.change(&uri, 5, "#declare A = 1;\n#include \"part.inc\"\n");
    let diagnostics = server.diagnostics(5);
    assert_eq!(diagnostics.len(), 1, "{diagnostics:?}");
    assert_eq!(diagnostics[0]["range"]["start"]["line"], json!(1));
    let message = diagnostics[0]["message"].as_str().unwrap_or("");
    assert!(message.contains("part.inc"), "{message}");
    server.finish();
}

#[test]
fn lsp_cuts_off_a_looping_scene_and_keeps_answering() {
    let uri = "file:///tmp/durer-lsp-loop/loop.pov";
    let mut server = Server::start(500);
    let start = Instant::now();
    server.open(
        uri,
        "#declare I = 0;\n#while (1)\n  #declare I = I + 1;\n#end\n",
    );
    // Requests are answered while the scene runs.
    let symbols = server.request(
        "textDocument/documentSymbol",
        json!({"textDocument": {"uri": uri}}),
    );
    assert_eq!(symbols.as_array().map(Vec::len), Some(2), "{symbols}");
    let diagnostics = server.diagnostics(1);
    let elapsed = start.elapsed();
    assert!(elapsed < Duration::from_secs(10), "{elapsed:?}");
    assert_eq!(diagnostics.len(), 1, "{diagnostics:?}");
    assert_eq!(diagnostics[0]["code"], json!("time-budget"));
    assert_eq!(diagnostics[0]["range"]["start"]["line"], json!(1));
    server.finish();
}

fn durer_check(scene: &std::path::Path, format: &str) -> (Option<i32>, String) {
    let output = Command::new(env!("CARGO_BIN_EXE_durer"))
        .args(["check", "--format", format])
        .arg(scene)
        .output()
        .expect("run durer");
    (
        output.status.code(),
        String::from_utf8_lossy(&output.stdout).into_owned(),
    )
}

/// Validates `document` against a JSON schema with Python's `jsonschema`, or says why not.
fn validate(schema: &std::path::Path, document: &str) -> Result<(), String> {
    let check = "import json,sys,jsonschema\nschema=json.load(open(sys.argv[1]))\nfor line in sys.stdin.read().splitlines():\n    jsonschema.validate(json.loads(line), schema)\n";
    let mut child = match Command::new("python3")
        .args(["-c", check])
        .arg(schema)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
    {
        Ok(child) => child,
        Err(e) => return Err(format!("skipped: python3 not available ({e})")),
    };
    child
        .stdin
        .take()
        .map(|mut s| s.write_all(document.as_bytes()));
    let output = child.wait_with_output().map_err(|e| e.to_string())?;
    let stderr = String::from_utf8_lossy(&output.stderr);
    if stderr.contains("No module named 'jsonschema'") {
        return Err("skipped: Python's jsonschema is not installed".into());
    }
    if output.status.success() {
        Ok(())
    } else {
        panic!("schema validation failed: {stderr}");
    }
}

#[test]
fn json_and_sarif_follow_their_schemas() {
    let dir = crate::scratch("formats");
    let scene = dir.join("broken.pov");
    std::fs::write(
        &scene,
        "#declare R = 2;\nsphere { 0, R pigment { color Whte } }\n",
    )
    .unwrap();
    let (code, json_text) = durer_check(&scene, "json");
    assert_eq!(code, Some(1));
    let line: Value = serde_json::from_str(json_text.trim()).expect("one JSON line");
    assert_eq!(line["line"], json!(2));
    assert_eq!(line["column"], json!(31));
    assert_eq!(line["code"], json!("eval"));
    assert_eq!(line["severity"], json!("error"));
    let (code, sarif_text) = durer_check(&scene, "sarif");
    assert_eq!(code, Some(1));
    let sarif: Value = serde_json::from_str(&sarif_text).expect("SARIF is JSON");
    assert_eq!(
        sarif["runs"][0]["results"][0]["locations"][0]["physicalLocation"]["region"]["startLine"],
        json!(2)
    );
    let schemas = crate::tests_folder().join("schemas");
    let docs_schema = crate::tests_folder()
        .join("..")
        .join("docs")
        .join("diagnostics.schema.json");
    for (schema, text) in [
        (docs_schema, json_text),
        (
            schemas.join("sarif-schema-2.1.0.json"),
            sarif_text.replace('\n', " "),
        ),
    ] {
        if let Err(why) = validate(&schema, &text) {
            println!("{why}");
            return;
        }
    }
}

#[test]
fn neovim_shows_the_diagnostic_line() {
    let dir = crate::scratch("neovim");
    let scene = dir.join("broken.pov");
    std::fs::write(
        &scene,
        "sphere { 0, 1\n  pigment { color rgb <1, 0, 0> }\n  finsh { phong 1 }\n}\n",
    )
    .unwrap();
    let init = crate::tests_folder()
        .join("integration")
        .join("lsp_neovim_init.lua");
    let output = Command::new("nvim")
        .args(["--headless", "--clean", "-u"])
        .arg(&init)
        .arg(&scene)
        .current_dir(&dir)
        .env("DURER", env!("CARGO_BIN_EXE_durer"))
        .stdin(Stdio::null())
        .output();
    let output = match output {
        Ok(output) => output,
        Err(e) => {
            println!("skipped: neovim is not installed ({e}); apt-get install -y neovim");
            return;
        }
    };
    let printed = String::from_utf8_lossy(&output.stdout);
    println!("neovim: {printed}");
    assert!(
        printed.contains("diagnostic line 3: unknown block keyword `finsh`"),
        "{printed}"
    );
}
