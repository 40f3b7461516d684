//! Typesetting speed of a ~30-page note (eight copies of the sample's body
//! sections, with the frame): the target is well under 2 s, so that a whole
//! `tmm run` with its note stays under 3 s.

#[path = "../tests/common/mod.rs"]
mod common;

use tmm_note::{Lang, typeset_with_warnings};

fn main() {
    divan::main();
}

#[divan::bench(sample_count = 5, sample_size = 1)]
fn thirty_pages_ru_frame(bencher: divan::Bencher) {
    let note = common::sample_note(Lang::Ru, true, 8);
    bencher.bench(|| {
        // Forget typst's memoized results: each run compiles from scratch, as
        // a one-shot `tmm run` does (only the fonts stay parsed).
        typst::comemo::evict(0);
        let t = typeset_with_warnings(divan::black_box(&note)).map(|t| (t.pages, t.pdf.len()));
        divan::black_box(t)
    });
}
