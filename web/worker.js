// Parses large logs off the main thread with the same wasm package, reports progress, and
// hands the columns back (transferred, not copied); the page rebuilds the Log from them.
import init, { Log } from "./pkg/gyrodrift.js";

const ready = init();

self.onmessage = async (ev) => {
  await ready;
  const { id, buffer } = ev.data;
  try {
    let last = 0;
    const log = Log.fromBytesWithProgress(new Uint8Array(buffer), (f) => {
      if (f - last >= 0.02) {
        last = f;
        self.postMessage({ id, progress: f });
      }
    });
    const data = log.toColumns();
    log.free();
    const transfer = [data.line.buffer, ...Object.values(data.columns).map((a) => a.buffer)];
    self.postMessage({ id, data }, transfer);
  } catch (e) {
    self.postMessage({ id, error: e.message });
  }
};
