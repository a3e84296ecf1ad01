// The browser's three modules as a bundler project (Vite, webpack) sees them: resolved by the
// package's "exports" without Node's condition, an ES2022 lib and skipLibCheck off, so each
// module's .d.ts compiles on its own (the chart module has no `Log` to name).
import init, { Log, hdr, runHdr, checkLog, type HdrResult, type CheckReport, type GapSplit } from "gyrodrift";
import initFull, { PipelineEstimator, importLog, type ImportResult, type PipelineState } from "gyrodrift/full";
import initPlot, { drawChart, chartCsv, type ChartSpec, type ChartLayout } from "gyrodrift/plot";

await init();
await initFull();
await initPlot();
const log: Log = Log.parse("time_s,gyro_dps,ref_heading_deg\n0,1,0\n1,1,0\n");
const r: HdrResult = hdr(log, {});
const report: CheckReport = checkLog(log);
const parts: GapSplit = log.splitAtGaps();
const heading: Float64Array = runHdr(log, {}).trace.heading_hdr_deg;
const live = new PipelineEstimator({ bias_s: 20 });
const s: PipelineState | null = live.state();
declare const imported: ImportResult;
const spec: ChartSpec = { series: [{ name: "heading", color: "#06c", x: heading, y: heading }] };
const layout: ChartLayout = drawChart(document.createElement("canvas"), spec);
const csv: string = chartCsv(spec);
{
  using disposed = Log.parse("time_s,gyro_dps\n0,1\n1,1\n");
  const rows: number = disposed.rowCount;
  void rows;
}
// @ts-expect-error: the chart module's spec is typed, a string is not a series
drawChart(document.createElement("canvas"), { series: "heading" });
export { r, report, parts, s, imported, layout, csv };
