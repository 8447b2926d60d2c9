//! speclab's tools: the speed–accuracy chart's drawing ([`chart`]), the
//! fitted rules' picture ([`fits`]) and the render survey's chart
//! ([`render_chart`]), used by the `chart`, `fits` and `render-chart`
//! binaries and their tests. The benchmarks are in `benches/`.

pub mod chart;
pub mod fits;
pub mod render_chart;
