use pest::Parser;
fn main() {
    let mut ok = 0; let mut bad = 0;
    for path in std::env::args().skip(1) {
        let bytes = std::fs::read(&path).unwrap();
        let text = String::from_utf8_lossy(&bytes);
        match durer::syntax::SdlParser::parse(durer::syntax::Rule::file, &text) {
            Ok(_) => ok += 1,
            Err(e) => { bad += 1; println!("{path}: {}", e.to_string().lines().take(4).collect::<Vec<_>>().join(" | ")); }
        }
    }
    println!("ok {ok} bad {bad}");
}
