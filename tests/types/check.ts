// Compiled with `tsc --noEmit`: the package's types describe options and results (no `any`).
import { checkOptions, version, compareTable, reportCsv, Log, hdr, runHdr, HdrEstimator, report, tune, simulate, importLog, detectImport, draftRecipe, columnGuesses, isDriveLog, pipeline, runPipeline, pipelineTrack, track, compare, checkLog, battery, batteryMarkdown, PipelineEstimator, addGyroErrors, batteryProfiles } from "gyrodrift";
import type { HdrOptions, HdrResult, HdrRun, HdrState, Report, TuneReport, CalibrationRun, Recipe, ImportResult, Detection, Draft, ColumnGuesses, PipelineResult, PipelineRun, PipelineTracks, Tracks, Compare, CheckReport, CheckFinding, GapSplit, ParseError, RefusalCode, CheckRefusal, Battery, BatteryCase, PipelineState, GyroErrors, BatteryProfile } from "gyrodrift";

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
const t: TuneReport = tune([log], undefined, { max_iters: 10, cross_validate: true, regularization_deg_per_min: 0.05 });
const tcv: number | undefined = t.result.cv?.cv_tuned_deg_per_min;
const trec: boolean = t.result.recommended_is_tuned;
const sim: Log = simulate({ kind: "drive", scenario: "city", minutes: 5, seed: 1, errors: { bias_dps: 1, cut_lead_in: true } });
const profiles: BatteryProfile[] = batteryProfiles();
const mems: GyroErrors = { ...profiles[0].errors, walk_dps_per_sqrt_s: 0.003 };
const worse: Log = addGyroErrors(sim, mems);
const cutFlag: boolean = profiles[0].errors.cut_lead_in;
// @ts-expect-error: gyro errors are typed, a yes/no is not a number
addGyroErrors(sim, { gyro_only: 1 });
declare const cal: CalibrationRun;
const c0: number = cal.C[0][0] + cal.sets[0].w_g_dps;
// @ts-expect-error: options are typed, a string is not a number
hdr(log, { tau_s: "fast" });
// @ts-expect-error: results are typed, no such key
r.E_psi_gyro_deg;
const recipe: Recipe = {
  table: [{ id: "imu", file: "imu.csv", time: { column: "t", unit: "ms" } }],
  yaw_rate: { table: "imu", axes: ["gx", "gy", "gz"], gravity: { axes: ["ax", "ay", "az"] }, unit: "rad/s", positive: "cw" },
  heading: { source: "column", table: "imu", column: "yaw", unit: "deg", positive: "ccw" },
};
const imp: ImportResult = importLog(recipe, { "imu.csv": new Uint8Array(0) });
const det: Detection = detectImport({ "Gyroscope.csv": new Uint8Array(0) });
const detected: ImportResult = importLog(det.recipe, {});
const roles: [string, string][] = det.used;
const isLog: boolean = isDriveLog("a.csv", new Uint8Array(0));
const draft: Draft = draftRecipe({ "mine.csv": new Uint8Array(0) });
const draftLines: string[] = draft.guesses;
const guessed: ColumnGuesses = columnGuesses({ "mine.csv": new Uint8Array(0) });
const rateColumn: string | undefined = guessed.yaw_rate?.column;
const timeUnit: "s" | "ms" | "us" | "ns" | "iso8601" | "time_of_day" = guessed.files[0].columns[0].time;
const sentence: string | undefined = guessed.files[0].nmea;
void detected; void roles; void isLog; void draftLines; void rateColumn; void timeUnit; void sentence;
const rows: number = imp.log.rowCount + imp.summary.n_reference;
const pr: PipelineResult = pipeline(log, { road_gate_dps: 0.5, still: { still_speed_mps: 0.3 } });
const pe: number = pr.E_psi_pipeline_deg + pr.NE_psi_pipeline_deg_per_min + pr.improvement_pipeline;
const prun: PipelineRun = runPipeline(log, {});
const stops: Uint8Array = prun.trace.stop;
const smoothed: Float64Array = prun.trace.heading_smoothed_deg;
const scored: boolean = log.hasReference;
void scored;
const paths: PipelineTracks = pipelineTrack(log, { bias_s: 10 });
const tracks: Tracks = track(log, {});
const ends: number = paths.pipeline.x_m[0] + paths.smoothed.y_m[0] + tracks.hdr.x_m[0] + (tracks.reference?.y_m[0] ?? 0);
void ends;
const ps: number = pr.NE_psi_pipeline_smoothed_deg_per_min + cmp0().mean.pipeline_smoothed;
function cmp0(): Compare {
  return compare([log], { warm_sigma_dps: 0.3, max_bias_dps: 5 });
}
const cmp: Compare = compare([log], {});
const cm: number = cmp.mean.pipeline;
// @ts-expect-error: a recipe's rate unit is one of the named units
const badRecipe: Recipe = { ...recipe, yaw_rate: { ...recipe.yaw_rate, unit: "furlongs" } };
// @ts-expect-error: pipeline results are typed, no such key
pr.E_psi_kalman_deg;
const chk: CheckReport = checkLog(log);
const fix: string | null = chk.findings[0]?.fix ?? null;
const fixValue: string | null = chk.findings[0]?.fix_value ?? null;
const gap: number = chk.gaps_s[0]?.[1] ?? 0;
// @ts-expect-error: a finding's code is one of the named checks
const badCode: CheckFinding["code"] = "colour";
const noRef: CheckFinding["code"] = "no_reference";
void noRef;
try {
  Log.parse("time_s,gyro_dps\n0,1\n0,1\n");
} catch (e) {
  const code: RefusalCode | undefined = (e as ParseError).code;
  // @ts-expect-error: a refusal's code is one of the named kinds
  const badRefusal: RefusalCode = "time_travel";
  void code, badRefusal;
}
try {
  report([log], {});
} catch (e) {
  const refused: string = (e as CheckRefusal).code === "check" ? (e as CheckRefusal).log : "";
  void refused;
}
const ver: string = version();
const tables: string = compareTable([log], {}, "csv") + reportCsv([log], {});
const why: string | undefined = checkOptions("hdr", { i_c_dps: -1 });
const split: GapSplit = log.splitAtGaps(undefined);
const part: Log | undefined = split.parts[0];
const gapLine: number = split.gaps[0]?.line ?? 0;
export { e, h, psi, st, rep, t, tcv, trec, sim, c0, rows, pe, stops, smoothed, ps, cm, badRecipe, chk, fix, fixValue, gap, badCode, split, part, gapLine, why, ver, tables };
const bat: Battery = battery([log], { warm_sigma_dps: 0.3 });
const firstCase: BatteryCase | undefined = bat.cases[0];
const within: number = (bat.added?.n_within ?? 0) + (firstCase?.ne_psi[firstCase.best] ?? 0);
const goalHolds: boolean = bat.added?.goals[0]?.holds ?? false;
const batMd: string = batteryMarkdown([log], {});
// @ts-expect-error: the battery's summary is typed, no such key
bat.added?.n_cases_within;

const live = new PipelineEstimator({ bias_s: 20 });
const livePsi: number = live.update(0, 0.1, 0) + live.updateMany(new Float64Array([1]), new Float64Array([0.1]), new Float64Array([NaN]))[0]!;
const liveState: PipelineState | null = live.state();
const liveSigma: number = (liveState?.heading_sigma_deg ?? 0) + live.headingSigmaDeg + live.headingDeg;
// @ts-expect-error: the speed is an argument of every row
live.update(0, 0.1);
export { livePsi, liveSigma };
// A live estimator saved and resumed (bytes to store anywhere; Python's save_state alike).
const saved: Uint8Array = live.saveState();
const resumed: PipelineEstimator = PipelineEstimator.fromState(saved);
const hdrResumed: HdrEstimator = HdrEstimator.fromState(est.saveState());
// @ts-expect-error: a state is bytes, not the estimator's settings
PipelineEstimator.fromState({ bias_s: 20 });
export { resumed, hdrResumed };
