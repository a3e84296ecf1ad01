#!/usr/bin/env bash
# Command 2 of the README: installs whatever the tests need (wasm target, wasm-bindgen CLI,
# node tools, Debian's chromium, a Python venv in tools/venv), builds, checks format and lints, and runs every test: native (unit, property,
# integration, CLI), wasm under Node (wasm-bindgen-test), the npm package under Node, the
# TypeScript types, the Python package (pytest, with the Dask fleet job), and the dashboard
# in headless Chromium (with the npm package bundled by Vite and webpack). Exits non-zero if any failed.
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"

ensure_wasm_target
ensure_lint_tools
ensure_node_tools
ensure_wasm_bindgen
ensure_chromium
ensure_python
build_cli
build_wasm
build_python

passed=0
failed=0
failures=()
suite() {
  local name="$1"
  shift
  say "$name"
  if "$@"; then
    passed=$((passed + 1))
  else
    failed=$((failed + 1))
    failures+=("$name")
  fi
}

suite "format (cargo fmt --check)" cargo fmt --all -- --check
# The workspace as the fronts build it, and the core crate alone with no feature (as the
# page's size-budgeted core module builds it: code only a feature uses must not warn there).
lint() { cargo clippy --workspace --all-targets -- -D warnings && cargo clippy -p gyrodrift --lib -- -D warnings; }
suite "lint (cargo clippy -D warnings)" lint
# The core crate's API docs (Rust users read them): no broken or private links, every feature.
suite "API docs (cargo doc -D warnings)" env RUSTDOCFLAGS="-D warnings" cargo doc -q --no-deps -p gyrodrift --all-features
suite "native tests (cargo test --workspace)" cargo test --workspace --no-fail-fast
suite "wasm tests under Node (wasm-bindgen-test)" \
  cargo test -p gyrodrift-wasm --target wasm32-unknown-unknown --tests --no-fail-fast
suite "npm package and Node example (node --test)" node --test tests/node/
# The types as Node resolves them, and as a bundler project does (ES2022 lib, skipLibCheck off).
typecheck() { tsc -p tests/types && tsc -p tests/types/bundler; }
suite "TypeScript types (tsc --noEmit)" typecheck
suite "Python package and Dask fleet job (pytest)" "$TOOLS/venv/bin/python" -m pytest -q -p no:logging python/tests
if [ -d tests/browser ]; then
  suite "dashboard in headless Chromium (playwright-core)" node --test --test-concurrency=1 tests/browser/
fi

echo
for f in "${failures[@]}"; do echo "FAILED: $f"; done
echo "suites: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
