// Removes the JSDoc blocks wasm-bindgen copies into a browser module's JS glue: the page
// never reads them, and the package's .d.ts (which editors and TypeScript read, through the
// glue's `@ts-self-types` line) keeps every one. 3.5 KB gzipped off the core module
// (BENCHMARKS.md). Usage: node scripts/strip-jsdoc.mjs FILE.js
import { readFileSync, writeFileSync } from "node:fs";

const file = process.argv[2];
const src = readFileSync(file, "utf8");
// A block starts a line (after indentation) with "/**" and ends at the first "*/"; the
// glue's strings and code never start a line so.
const out = src.replace(/^[ \t]*\/\*\*[\s\S]*?\*\/[ \t]*\n/gm, "");
if (!out.includes("@ts-self-types")) throw new Error(`${file}: the @ts-self-types line is gone`);
writeFileSync(file, out);
