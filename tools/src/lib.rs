//! speclab's tools: the speed–accuracy chart's drawing ([`chart`]), used by
//! the `chart` binary and its tests. The benchmarks are in `benches/`.

pub mod chart;
