//! AFL++ target: each input is a scene text, run through durer::fuzzing::eval.
fn main() {
    let limits = durer::fuzzing::Limits::default();
    afl::fuzz!(|data: &[u8]| {
        std::hint::black_box(durer::fuzzing::evaluate(data, &limits));
    });
}
