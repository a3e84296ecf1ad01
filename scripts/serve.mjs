#!/usr/bin/env node
// A static file server for the dashboard on 127.0.0.1 (no server logic): web/ at / (the
// build copies the sample logs into web/sample-logs/). Usage: node scripts/serve.mjs [port]
import { createServer } from "node:http";
import { createReadStream, statSync } from "node:fs";
import { extname, join, normalize, resolve } from "node:path";
import { fileURLToPath } from "node:url";

const root = resolve(fileURLToPath(import.meta.url), "..", "..");
const port = Number(process.argv[2] || process.env.PORT || 8080);
const types = {
  ".html": "text/html; charset=utf-8",
  ".js": "text/javascript; charset=utf-8",
  ".mjs": "text/javascript; charset=utf-8",
  ".css": "text/css; charset=utf-8",
  ".wasm": "application/wasm",
  ".json": "application/json",
  ".csv": "text/csv; charset=utf-8",
  ".png": "image/png",
  ".svg": "image/svg+xml",
  ".md": "text/markdown; charset=utf-8",
};

function resolvePath(urlPath) {
  const p = decodeURIComponent(urlPath.split("?")[0]);
  const [base, rest] = [join(root, "web"), p];
  const full = normalize(join(base, rest));
  if (!full.startsWith(base)) return null; // no escaping the served folders
  try {
    const st = statSync(full);
    return st.isDirectory() ? join(full, "index.html") : full;
  } catch {
    return null;
  }
}

createServer((req, res) => {
  const file = resolvePath(req.url || "/");
  if (!file) {
    res.writeHead(404, { "content-type": "text/plain" }).end("not found");
    return;
  }
  res.writeHead(200, { "content-type": types[extname(file)] || "application/octet-stream", "cache-control": "no-cache" });
  createReadStream(file).on("error", () => res.end()).pipe(res);
}).listen(port, "127.0.0.1", () => {
  console.log(`gyrodrift dashboard: http://127.0.0.1:${port}/`);
});
