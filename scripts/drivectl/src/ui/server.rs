//! The HTTP side of `drivectl ui`: static files compiled in, the JSON API.
use super::Shared;
use anyhow::Result;
use std::io::Read;
use std::sync::Arc;
use tiny_http::{Header, Method, Request, Response};

const PAGE: &str = include_str!("page.html");
const APP_JS: &str = include_str!("app.js");
const STYLE: &str = include_str!("style.css");
const UPLOT_JS: &str = include_str!("vendor/uplot/uPlot.iife.min.js");
const UPLOT_CSS: &str = include_str!("vendor/uplot/uPlot.min.css");
const UPLOT_LICENSE: &str = include_str!("vendor/uplot/LICENSE");

fn header(k: &str, v: &str) -> Header {
    Header::from_bytes(k.as_bytes(), v.as_bytes()).expect("ASCII header")
}

fn text(body: &str, mime: &str) -> Response<std::io::Cursor<Vec<u8>>> {
    Response::from_string(body)
        .with_header(header("Content-Type", mime))
        .with_header(header("Cache-Control", "no-store"))
}

fn json(v: &serde_json::Value, status: u16) -> Response<std::io::Cursor<Vec<u8>>> {
    text(&v.to_string(), "application/json").with_status_code(status)
}

/// The value of `key` in the query string `q` (no percent-decoding: the
/// values are numbers and channel names).
fn query<'a>(q: &'a str, key: &str) -> Option<&'a str> {
    q.split('&')
        .find_map(|kv| kv.strip_prefix(key)?.strip_prefix('='))
}

fn handle(shared: &Shared, mut req: Request) {
    let url = req.url().to_string();
    let (path, q) = url.split_once('?').unwrap_or((&url, ""));
    let resp = match (req.method(), path) {
        (Method::Get, "/") => text(PAGE, "text/html; charset=utf-8"),
        (Method::Get, "/app.js") => text(APP_JS, "text/javascript; charset=utf-8"),
        (Method::Get, "/style.css") => text(STYLE, "text/css; charset=utf-8"),
        (Method::Get, "/vendor/uPlot.iife.min.js") => {
            text(UPLOT_JS, "text/javascript; charset=utf-8")
        }
        (Method::Get, "/vendor/uPlot.min.css") => text(UPLOT_CSS, "text/css; charset=utf-8"),
        (Method::Get, "/vendor/uPlot.LICENSE") => text(UPLOT_LICENSE, "text/plain; charset=utf-8"),
        (Method::Get, "/api/tel") => {
            let since = query(q, "since").and_then(|v| v.parse().ok()).unwrap_or(0);
            json(&shared.tel_since(since), 200)
        }
        (Method::Post, "/api/cmd") => {
            let mut body = String::new();
            let r = match req.as_reader().take(4096).read_to_string(&mut body) {
                Ok(_) => shared.command(&body),
                Err(e) => Err(e.into()),
            };
            result(r)
        }
        (Method::Post, "/api/tel/start") => {
            let rate = query(q, "rate").and_then(|v| v.parse().ok());
            let channels: Vec<String> = query(q, "channels")
                .unwrap_or("")
                .split(',')
                .map(str::to_string)
                .collect();
            match rate {
                Some(rate) => result(shared.tel_start(rate, &channels)),
                None => json(
                    &serde_json::json!({"error": "rate must be a whole number"}),
                    400,
                ),
            }
        }
        (Method::Post, "/api/tel/stop") => result(shared.command("tel stop")),
        _ => text("not found", "text/plain").with_status_code(404),
    };
    let _ = req.respond(resp);
}

fn result(r: Result<serde_json::Value>) -> Response<std::io::Cursor<Vec<u8>>> {
    match r {
        Ok(v) => json(&v, 200),
        Err(e) => json(&serde_json::json!({"error": format!("{e:#}")}), 500),
    }
}

/// Serves until the process ends: one thread per request, so that a long
/// command (`sweep`) does not hold up the telemetry polls.
pub fn serve(http: tiny_http::Server, shared: Arc<Shared>) -> Result<()> {
    for req in http.incoming_requests() {
        let shared = shared.clone();
        std::thread::spawn(move || handle(&shared, req));
    }
    Ok(())
}
