// The full module in a Web Worker, as the dashboard loads it: a log's columns in, the
// recommended pipeline's NE_psi out.
import init, { Log, pipeline } from "gyrodrift/full";

self.onmessage = async (e) => {
  try {
    await init();
    self.postMessage(pipeline(Log.fromColumns(e.data)).NE_psi_pipeline_deg_per_min);
  } catch (err) {
    self.postMessage(`error: ${err.message}`);
  }
};
