//! The pipeline and the import on whole logs: a 52 min drive end to end (still blocks,
//! pipeline, Table-III HDR, both peers, metrics) and one real-log recipe import.
//! Run: cargo bench -p gyrodrift --bench pipeline

use criterion::{criterion_group, criterion_main, Criterion};
use gyrodrift::pipeline::{self, PipelineParams};
use std::hint::black_box;

fn bench(c: &mut Criterion) {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../sample-logs/train/highway-1.csv");
    let log = gyrodrift::parse_log(std::fs::File::open(path).unwrap()).unwrap();
    let p = PipelineParams::default();
    let mut g = c.benchmark_group("highway-1_52min_31k_rows");
    g.sample_size(20);
    g.bench_function("pipeline_run_all_methods", |b| b.iter(|| pipeline::run(black_box(&log), &p).unwrap()));
    let blocks = gyrodrift::still::blocks(&log, 20.0, &p.still).unwrap();
    g.bench_function("pipeline_blocks_only", |b| b.iter(|| pipeline::run_blocks(black_box(&blocks), p, 20.0).unwrap()));
    g.bench_function("hdr_run", |b| b.iter(|| gyrodrift::hdr::run(black_box(&log), &Default::default()).unwrap()));
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
