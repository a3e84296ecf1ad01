#!/usr/bin/env node
// HDR over 10 M samples in Node: the wasm package (HdrEstimator.updateMany, 1 M-sample
// chunks) vs a straightforward hand-written JavaScript HDR, on the same samples as the
// criterion benchmark (core/benches/hdr.rs). Run after the package is built:
//   node tests/bench/hdr-node.mjs
import { HdrEstimator } from "gyrodrift";

const N = 10_000_000;
const t = new Float64Array(N);
const w = new Float64Array(N);
// Same samples as core/benches/hdr.rs (BigInt LCG for exact 64-bit arithmetic).
let s = 7n;
const M = (1n << 64n) - 1n;
for (let i = 0; i < N; i++) {
  s = (s * 6364136223846793005n + 1442695040888963407n) & M;
  const noise = (Number(s >> 11n) / 2 ** 53 - 0.5) * 0.2;
  const turn = Math.floor(i / 300) % 7 === 0 ? 9.0 : 0.0;
  t[i] = i * 0.1;
  w[i] = 0.5 + turn + noise;
}

/** What a web developer would write from the paper (methods.md reading, Table III). */
function hdrJs(t, w, eps0) {
  const ic = 0.0422, tau = 0.75, thw = 0.564, c1 = 0.16, c2 = 1.8;
  const sign = (x) => (x > 0 ? 1 : x < 0 ? -1 : 0);
  let x0 = w[0] - eps0;
  let wf = x0, I = 0, r = 1, o1 = x0, o2 = x0, psi = 0, tp = t[0];
  for (let i = 1; i < t.length; i++) {
    const T = t[i] - tp;
    tp = t[i];
    const x = w[i] - eps0;
    wf = (x * T + tau * wf) / (T + tau);
    const W = Math.abs(o1) < thw ? 1 : 0;
    r = sign(o1) === sign(o2) ? r + 1 : 1;
    const R = (1 + c1) / (1 + c1 * Math.pow(r, c2));
    I = I - sign(o1) * W * R * ic * T;
    const om = wf + I;
    const od = om + (tau / T) * (om - o1);
    psi += od * T;
    o2 = o1;
    o1 = om;
  }
  return psi;
}

function time(label, fn, reps = 3) {
  let best = Infinity, out;
  for (let k = 0; k < reps; k++) {
    const a = process.hrtime.bigint();
    out = fn();
    const ns = Number(process.hrtime.bigint() - a);
    best = Math.min(best, ns);
  }
  console.log(`${label.padEnd(34)} ${(best / 1e6).toFixed(1).padStart(8)} ms  ${(best / N).toFixed(2).padStart(6)} ns/sample  (heading ${out.toFixed(6)})`);
  return best;
}

const CHUNK = 1_000_000;
const wasmNs = time("wasm HdrEstimator.updateMany", () => {
  const est = new HdrEstimator({}, 0.5);
  let last = 0;
  for (let i = 0; i < N; i += CHUNK) {
    const h = est.updateMany(t.subarray(i, i + CHUNK), w.subarray(i, i + CHUNK));
    last = h[h.length - 1];
  }
  est.free();
  return last;
});
const jsNs = time("hand-written JavaScript HDR", () => hdrJs(t, w, 0.5));
console.log(`wasm / JS = ${(wasmNs / jsNs).toFixed(2)}`);
