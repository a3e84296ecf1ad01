#!/usr/bin/env bash
# Command 1 of the README: installs whatever is missing (wasm target, the wasm-bindgen CLI
# matching Cargo.lock, node tools), builds the CLI and the wasm package, and serves the
# dashboard on http://127.0.0.1:${PORT:-8080}/ with a sample drive loaded.
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
ensure_wasm_target
ensure_node_tools
ensure_wasm_bindgen
build_cli
build_wasm
say "serving (Ctrl-C to stop)"
exec node scripts/serve.mjs "${PORT:-8080}"
