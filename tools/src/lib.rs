//! speclab's tools: the speed–accuracy chart's drawing ([`chart`]) and the
//! fitted rules' picture ([`fits`]), used by the `chart` and `fits`
//! binaries and their tests. The benchmarks are in `benches/`.

pub mod chart;
pub mod fits;
