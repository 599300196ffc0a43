//! Nothing: the benchmarks are in `benches/` (a package needs a target of its own to hold them).
