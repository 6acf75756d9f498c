//! The live preview page of `durer watch --serve`: `GET /` the page, `GET /image.png` the
//! latest image, `GET /state` the state as JSON, `GET /events` server-sent events (one
//! `state` event per change: status, image size and pass, diagnostics, statistics).
//!
//! tiny_http serves each request on its own thread; the event stream writes to the raw
//! connection and flushes per event (tiny_http's chunked responses buffer).

use serde_json::{json, Value};
use std::io::Write;
use std::sync::{Arc, Condvar, Mutex};
use std::time::Duration;

/// The page (HTML, CSS and script in one file).
const PAGE: &str = include_str!("page.html");

/// What the page shows; every change bumps `version` and wakes the event streams.
#[derive(Default)]
pub struct Live {
    state: Mutex<State>,
    changed: Condvar,
}

#[derive(Default)]
struct State {
    version: u64,
    status: String,
    png: Option<Arc<Vec<u8>>>,
    image: Value,
    image_version: u64,
    diagnostics: Value,
    stats: Value,
}

impl Live {
    fn update(&self, change: impl FnOnce(&mut State)) {
        let mut state = self.state.lock().unwrap_or_else(|e| e.into_inner());
        change(&mut state);
        state.version += 1;
        self.changed.notify_all();
    }

    pub fn set_status(&self, status: &str) {
        self.update(|s| s.status = status.to_string());
    }

    pub fn set_diagnostics(&self, diagnostics: Value) {
        self.update(|s| s.diagnostics = diagnostics);
    }

    pub fn set_image(&self, png: Vec<u8>, image: Value, stats: Value) {
        self.update(|s| {
            s.png = Some(Arc::new(png));
            s.image = image;
            s.image_version = s.version + 1;
            s.stats = stats;
        });
    }

    fn json(state: &State) -> Value {
        json!({
            "version": state.version,
            "status": state.status,
            "image": if state.png.is_some() {
                json!({ "url": format!("/image.png?v={}", state.image_version),
                        "info": state.image })
            } else {
                Value::Null
            },
            "diagnostics": state.diagnostics,
            "stats": state.stats,
        })
    }

    /// The state after `seen` changes (waits up to `timeout`; `None` when nothing changed).
    fn next(&self, seen: u64, timeout: Duration) -> Option<(u64, Value)> {
        let state = self.state.lock().unwrap_or_else(|e| e.into_inner());
        let (state, _) = self
            .changed
            .wait_timeout_while(state, timeout, |s| s.version == seen)
            .unwrap_or_else(|e| e.into_inner());
        (state.version != seen).then(|| (state.version, Live::json(&state)))
    }
}

/// Starts serving on `address`; returns the address bound (the port may have been 0).
pub fn start(address: &str, live: Arc<Live>) -> Result<String, String> {
    let server = tiny_http::Server::http(address).map_err(|e| e.to_string())?;
    let bound = server
        .server_addr()
        .to_ip()
        .map_or_else(|| address.to_string(), |a| a.to_string());
    if let Some(ip) = server.server_addr().to_ip() {
        if !ip.ip().is_loopback() {
            eprintln!(
                "durer: warning: the preview is served on {ip}, reachable from other machines"
            );
        }
    }
    std::thread::spawn(move || {
        for request in server.incoming_requests() {
            let live = live.clone();
            std::thread::spawn(move || respond(request, &live));
        }
    });
    Ok(bound)
}

/// `response` with a `Content-Type` and `Cache-Control: no-store`.
fn typed<R: std::io::Read>(
    mut response: tiny_http::Response<R>,
    content_type: &str,
) -> tiny_http::Response<R> {
    for (name, value) in [
        ("Content-Type", content_type),
        ("Cache-Control", "no-store"),
    ] {
        if let Ok(header) = tiny_http::Header::from_bytes(name.as_bytes(), value.as_bytes()) {
            response = response.with_header(header);
        }
    }
    response
}

fn respond(request: tiny_http::Request, live: &Live) {
    let path = request.url().split('?').next().unwrap_or("/").to_string();
    let _ = match path.as_str() {
        "/" | "/index.html" => request.respond(typed(
            tiny_http::Response::from_string(PAGE),
            "text/html; charset=utf-8",
        )),
        "/image.png" => {
            let png = live
                .state
                .lock()
                .unwrap_or_else(|e| e.into_inner())
                .png
                .clone();
            match png {
                Some(png) => request.respond(typed(
                    tiny_http::Response::from_data(png.as_slice()),
                    "image/png",
                )),
                None => request.respond(tiny_http::Response::empty(404)),
            }
        }
        "/state" => {
            let state = Live::json(&live.state.lock().unwrap_or_else(|e| e.into_inner()));
            request.respond(typed(
                tiny_http::Response::from_string(state.to_string()),
                "application/json",
            ))
        }
        "/events" => {
            events(request.into_writer(), live);
            Ok(())
        }
        _ => request.respond(tiny_http::Response::empty(404)),
    };
}

/// The event stream: the current state at once, then each change; a comment every 15 s
/// finds closed connections.
fn events(mut writer: Box<dyn Write + Send>, live: &Live) {
    let head = "HTTP/1.1 200 OK\r\nContent-Type: text/event-stream\r\n\
                Cache-Control: no-store\r\nConnection: close\r\n\r\n";
    if writer.write_all(head.as_bytes()).is_err() {
        return;
    }
    let mut seen = u64::MAX;
    loop {
        let message = match live.next(seen, Duration::from_secs(15)) {
            Some((version, state)) => {
                seen = version;
                format!("event: state\ndata: {state}\n\n")
            }
            None => ": still here\n\n".to_string(),
        };
        if writer
            .write_all(message.as_bytes())
            .and_then(|()| writer.flush())
            .is_err()
        {
            return;
        }
    }
}
