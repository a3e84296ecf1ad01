// A web tool's page as its authors would write it against the npm package: the core module on
// the page, the full module in a Web Worker, the chart module for a chart. The bundler test
// (tests/browser/bundlers.test.mjs) builds it with Vite and webpack and reads #out.
import init, { Log, hdr } from "gyrodrift";
import initPlot, { drawChart } from "gyrodrift/plot";

const out = document.getElementById("out");
try {
  await init();
  const log = Log.parse(await (await fetch("city-1.csv")).text());
  const hdrResult = hdr(log, {});
  const worker = new Worker(new URL("./worker.js", import.meta.url), { type: "module" });
  const fromWorker = await new Promise((resolve, reject) => {
    worker.onmessage = (e) => resolve(e.data);
    worker.onerror = (e) => reject(new Error(`worker: ${e.message}`));
    worker.postMessage(log.toColumns());
  });
  await initPlot();
  const { columns } = log.toColumns();
  const layout = drawChart(document.getElementById("chart"), {
    title: "yaw rate",
    series: [{ name: "gyro", color: "#0066cc", x: columns.time_s, y: columns.gyro_dps }],
  });
  out.textContent = JSON.stringify({
    hdr: hdrResult.NE_psi_hdr_deg_per_min,
    pipeline: fromWorker,
    plot_width: layout.right - layout.left,
  });
} catch (e) {
  out.textContent = `error: ${e.message}`;
}
