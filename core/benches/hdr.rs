//! HDR over 10 M samples vs a bare integration pass (psi += rate * T) over the same samples.
//! Run: cargo bench -p gyrodrift --bench hdr

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use gyrodrift::hdr::{Hdr, HdrParams};
use std::hint::black_box;

const N: usize = 10_000_000;

/// 10 Hz samples: a slowly drifting bias plus turns and noise from a fixed LCG.
fn samples() -> (Vec<f64>, Vec<f64>) {
    let mut s: u64 = 7;
    let mut t = Vec::with_capacity(N);
    let mut w = Vec::with_capacity(N);
    for i in 0..N {
        s = s.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        let noise = ((s >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * 0.2;
        let turn = if (i / 300) % 7 == 0 { 9.0 } else { 0.0 };
        t.push(i as f64 * 0.1);
        w.push(0.5 + turn + noise);
    }
    (t, w)
}

fn bench(c: &mut Criterion) {
    let (t, w) = samples();
    let mut g = c.benchmark_group("10M_samples");
    g.sample_size(10);
    g.throughput(Throughput::Elements(N as u64));
    g.bench_function("bare_integration", |b| {
        b.iter(|| {
            let (t, w) = (black_box(&t), black_box(&w));
            let mut psi = 0.0;
            let mut last = t[0];
            for i in 0..t.len() {
                psi += w[i] * (t[i] - last);
                last = t[i];
            }
            psi
        })
    });
    g.bench_function("hdr_update_slice", |b| {
        b.iter(|| {
            let (t, w) = (black_box(&t), black_box(&w));
            let mut h = Hdr::new(HdrParams::default(), 0.5).unwrap();
            let mut psi = 0.0;
            h.update_slice(t, w, |o| psi = o.heading_deg).unwrap();
            psi
        })
    });
    g.bench_function("hdr_update", |b| {
        b.iter(|| {
            let (t, w) = (black_box(&t), black_box(&w));
            let mut h = Hdr::new(HdrParams::default(), 0.5).unwrap();
            let mut psi = 0.0;
            for i in 0..t.len() {
                psi = h.update(t[i], w[i]).unwrap().heading_deg;
            }
            psi
        })
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
