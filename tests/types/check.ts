// Compiled with `tsc --noEmit`: the package's types describe options and results (no `any`).
import { Log, hdr, runHdr, HdrEstimator, report, tune, simulate } from "gyrodrift";
import type { HdrOptions, HdrResult, HdrRun, HdrState, Report, TuneReport, CalibrationRun } from "gyrodrift";

const log: Log = Log.parse("time_s,gyro_dps,ref_heading_deg\n0,1,0\n1,1,0\n");
const opts: HdrOptions = { i_c_dps: 0.0422, tau_s: 0.75, resample: true };
const r: HdrResult = hdr(log, opts);
const e: number = r.E_psi_hdr_deg + r.NE_psi_hdr_deg_per_min + r.improvement;
const run: HdrRun = runHdr(log, {});
const h: Float64Array = run.trace.heading_hdr_deg;
const est = new HdrEstimator({ c1: 0.16 }, 0.5);
const psi: number = est.update(0, 1.2);
const st: HdrState | null = est.state();
const rep: Report = report([log], {});
const t: TuneReport = tune([log], undefined, { max_iters: 10 });
const sim: Log = simulate({ kind: "drive", scenario: "city", minutes: 5, seed: 1 });
declare const cal: CalibrationRun;
const c0: number = cal.C[0][0] + cal.sets[0].w_g_dps;
// @ts-expect-error: options are typed, a string is not a number
hdr(log, { tau_s: "fast" });
// @ts-expect-error: results are typed, no such key
r.E_psi_gyro_deg;
export { e, h, psi, st, rep, t, sim, c0 };
