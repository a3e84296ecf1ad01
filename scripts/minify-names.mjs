// Renames a browser module's glue to the names `wasm-opt --minify-imports-and-exports-and-modules`
// gave its wasm: each `wasm.NAME` export the glue calls, each import key the glue hands it,
// and the import module's name; the .d.ts files' raw export lists follow. The names are
// the wasm's own business (the package's API is the glue's), and short ones take 1.6 KB
// gzipped off the core module (BENCHMARKS.md).
// Usage: node scripts/minify-names.mjs NAMES.json DIR/NAME (NAME.js, NAME_bg.wasm, ...)
import { readFileSync, writeFileSync } from "node:fs";

const [mapFile, base] = process.argv.slice(2);
const map = JSON.parse(readFileSync(mapFile, "utf8"));
const exports = new Map(map.exports.map(([name, short]) => [name, short]));
const imports = new Map(map.imports.map(([, name, short]) => [name, short]));
const modules = new Set(map.imports.map(([module]) => module));
const wasm = new WebAssembly.Module(readFileSync(`${base}_bg.wasm`));
const shortModules = new Set(WebAssembly.Module.imports(wasm).map((i) => i.module));
if (modules.size !== 1 || shortModules.size !== 1) throw new Error(`${base}_bg.wasm: one import module expected`);
const [module] = modules;
const [shortModule] = shortModules;

const rename = (src, pattern, names, what) => {
  const seen = new Set();
  const out = src.replace(pattern, (whole, head, name, tail) => {
    if (!names.has(name)) return whole;
    seen.add(name);
    return `${head}${names.get(name)}${tail}`;
  });
  return { out, seen, what };
};
const mustHave = ({ seen, what }, names) => {
  const missing = [...names.keys()].filter((n) => !seen.has(n));
  if (missing.length) throw new Error(`${base}: ${what} not found: ${missing.join(", ")}`);
};

// The glue: exports as `wasm.NAME` (some exports it never calls), imports as the keys of
// its import object (each one the wasm imports must be there).
let js = rename(readFileSync(`${base}.js`, "utf8"), /(\bwasm\.)([\w$]+)()/g, exports, "exports the glue calls");
const unknown = [...js.out.matchAll(/\bwasm\.([\w$]+)/g)].map((m) => m[1]).filter((n) => ![...exports.values()].includes(n));
if (unknown.length) throw new Error(`${base}.js: calls exports the wasm does not have: ${unknown.join(", ")}`);
js = rename(js.out, /^(\s+)([\w$]+)(: function\b)/gm, imports, "imports the glue provides");
mustHave(js, imports);
const keyed = JSON.stringify(module) + ": import0";
if (!js.out.includes(keyed)) throw new Error(`${base}.js: no ${keyed}`);
writeFileSync(`${base}.js`, js.out.replace(keyed, `${JSON.stringify(shortModule)}: import0`));

// The types of the raw exports: `init`'s InitOutput (that interface alone: the API's own
// types have members of the same names) and the wasm's own .d.ts.
const dts = readFileSync(`${base}.d.ts`, "utf8");
const start = dts.indexOf("export interface InitOutput {");
const end = dts.indexOf("\n}", start);
if (start < 0 || end < 0) throw new Error(`${base}.d.ts: no InitOutput`);
const init = rename(dts.slice(start, end), /^(\s+readonly )([\w$]+)(:)/gm, exports, "exports typed").out;
writeFileSync(`${base}.d.ts`, dts.slice(0, start) + init + dts.slice(end));
const raw = readFileSync(`${base}_bg.wasm.d.ts`, "utf8");
writeFileSync(`${base}_bg.wasm.d.ts`, rename(raw, /^(export const )([\w$]+)(:)/gm, exports, "exports typed").out);
