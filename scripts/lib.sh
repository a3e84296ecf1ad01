# Shared steps of scripts/serve.sh and scripts/test.sh: each installs what is missing
# (idempotently) and builds. Sourced, not run.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
TOOLS="$ROOT/tools"
export PATH="$TOOLS/bin:$ROOT/tests/node_modules/.bin:$HOME/.cargo/bin:$PATH"
cd "$ROOT"

say() { printf '\n== %s\n' "$*"; }

ensure_wasm_target() {
  if ! rustup target list --installed | grep -qx wasm32-unknown-unknown; then
    say "adding the wasm32-unknown-unknown target"
    rustup target add wasm32-unknown-unknown
  fi
}

# rustfmt and clippy for the format and lint suite (in rustup's default profile; added if not).
ensure_lint_tools() {
  for c in rustfmt clippy; do
    if ! rustup component list --installed | grep -q "^$c"; then
      say "adding the $c component"
      rustup component add "$c"
    fi
  done
}

# The wasm-bindgen CLI must match the wasm-bindgen crate in Cargo.lock exactly.
ensure_wasm_bindgen() {
  local want have
  want=$(awk '/^name = "wasm-bindgen"$/ {getline; gsub(/"/, "", $3); print $3; exit}' Cargo.lock)
  have=$(wasm-bindgen --version 2>/dev/null | awk '{print $2}' || true)
  if [ "$have" != "$want" ]; then
    say "installing wasm-bindgen-cli $want into tools/ (about 2 min, once)"
    # --locked fails here (its lockfile names a crate the registry lacks), so no --locked.
    cargo install wasm-bindgen-cli --version "$want" --root "$TOOLS" --force
  fi
}

# Node tools of the build and the tests (binaryen's wasm-opt, typescript, playwright-core),
# pinned by tests/package-lock.json.
ensure_node_tools() {
  if [ ! -x tests/node_modules/.bin/wasm-opt ] || [ tests/package-lock.json -nt tests/node_modules/.stamp ]; then
    say "installing node tools (tests/package.json)"
    (cd tests && npm ci --no-audit --no-fund --loglevel=error && touch node_modules/.stamp)
  fi
}

ensure_chromium() {
  if ! command -v chromium >/dev/null 2>&1; then
    say "installing Debian's chromium for the browser tests"
    local sudo=""
    [ "$(id -u)" -eq 0 ] || sudo="sudo"
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq chromium chromium-driver >/dev/null
  fi
}

# A project-local virtual environment (tools/venv, ignored by git) with what the Python
# package needs to build (maturin) and to be tested (numpy, pandas, pyarrow, dask, pytest).
ensure_python() {
  local venv="$TOOLS/venv"
  if [ ! -x "$venv/bin/python" ]; then
    say "creating the Python virtual environment tools/venv"
    python3 -m venv "$venv"
  fi
  if [ ! -f "$venv/.stamp" ] || [ python/requirements-test.txt -nt "$venv/.stamp" ]; then
    say "installing the Python build and test packages (python/requirements-test.txt)"
    "$venv/bin/pip" install -q --disable-pip-version-check -r python/requirements-test.txt
    touch "$venv/.stamp"
  fi
}

# The Python package: an abi3 wheel by maturin into target/wheels, installed into tools/venv.
build_python() {
  say "building the Python wheel (python/, maturin)"
  rm -f target/wheels/gyrodrift-*.whl
  "$TOOLS/venv/bin/maturin" build --release -m python/Cargo.toml -o target/wheels -q
  "$TOOLS/venv/bin/pip" install -q --disable-pip-version-check --force-reinstall --no-deps target/wheels/gyrodrift-*.whl
}

# One wasm build through wasm-bindgen and wasm-opt: $1 cargo feature flags, $2 target
# (web|nodejs), $3 output folder, $4 module name, $5 wasm-opt's passes (default -Oz --converge).
# Panic locations name their source files: without the crate registry's absolute path
# (the same names on any machine, and 57 bytes less in the size-capped core module,
# BENCHMARKS.md). Prints the --config value for the wasm target's rustflags.
wasm_remap() {
  local home="${CARGO_HOME:-$HOME/.cargo}" flags="" d
  for d in "$home"/registry/src/*/; do
    [ -d "$d" ] && flags="$flags\"--remap-path-prefix=$d=\","
  done
  printf 'target.wasm32-unknown-unknown.rustflags=[%s]' "${flags%,}"
}

wasm_part() {
  # shellcheck disable=SC2086
  cargo build --profile wasm-release --target wasm32-unknown-unknown -p gyrodrift-wasm $1 --config "$(wasm_remap)"
  # TextEncoder.encodeInto only (every browser since 2021, Node 12+): no fallback glue,
  # 62 bytes gzipped off the core module (BENCHMARKS.md).
  wasm-bindgen --target "$2" --weak-refs --encode-into always --out-dir "$3" --out-name "$4" target/wasm32-unknown-unknown/wasm-release/gyrodrift_wasm.wasm
  # Its classes declare [Symbol.dispose] (for `using`): the types name the lib that declares
  # it, so a project checking them with an ES2022 lib and skipLibCheck off compiles as is.
  if grep -q 'Symbol.dispose' "$3/$4.d.ts"; then sed -i '1i /// <reference lib="esnext.disposable" />' "$3/$4.d.ts"; fi
  # The browser modules' glue without its JSDoc (the .d.ts keeps it): 3.5 KB gzipped.
  if [ "$2" = web ]; then node scripts/strip-jsdoc.mjs "$3/$4.js"; fi
  # shellcheck disable=SC2086
  local features="--enable-bulk-memory --enable-nontrapping-float-to-int --enable-sign-ext --enable-mutable-globals --enable-multivalue --enable-reference-types"
  # shellcheck disable=SC2086
  wasm-opt ${5:--Oz --converge} --strip-debug --strip-producers $features "$3/$4_bg.wasm" -o "$3/$4_bg.wasm"
  # "minify": the wasm's import and export names shortened, and the glue and types renamed
  # to match (scripts/minify-names.mjs); once, after the passes above (--converge would
  # rename again). -Oz again here: without it wasm-opt writes the module 0.7 KB larger.
  if [ "${6:-}" = minify ]; then
    # shellcheck disable=SC2086
    wasm-opt -Oz --minify-imports-and-exports-and-modules --strip-debug --strip-producers $features "$3/$4_bg.wasm" -o "$3/$4_bg.wasm" > "$3/names.json"
    node scripts/minify-names.mjs "$3/names.json" "$3/$4"
    rm "$3/names.json"
  fi
}

# The npm package in web/pkg: ES modules for browsers, CommonJS build for Node, types.
build_wasm() {
  say "building the wasm package into web/pkg (core, plot, full, node)"
  rm -rf web/pkg
  # The browser's main module: logs, methods, metrics, estimators (<= 200 KB gzipped);
  # charts and the rest (import, tuning, simulation) load as their own modules.
  # Its bindings at "z" (Cargo.toml says why): 4 KB smaller, the same speed. And the csv
  # crates at "z" and "s" here (0.5 KB): the page parses files over 4 MB in the worker's full
  # module, which keeps them at "s" and 3; this module parses 100 MB in 1.6-2.2 s, not 1.4-1.5
  # (BENCHMARKS.md).
  # wasm-opt restructures its control flow twice between -Oz passes (flatten, rereloop): the
  # first round took 0.6 KB gzipped off this module, the second 0.35 KB; a third adds bytes.
  # The same speed within this machine's noise (BENCHMARKS.md). Functions that differ only
  # in constants are merged first (--merge-similar-functions): 0.2 KB, the same speed.
  # Each browser module's wasm names are minified, its glue and types renamed to match
  # ("minify": 2.8 KB off this one; BENCHMARKS.md).
  wasm_part "--no-default-features --features core --config profile.wasm-release.package.gyrodrift-wasm.opt-level='z' --config profile.wasm-release.package.csv.opt-level='z' --config profile.wasm-release.package.csv-core.opt-level='s'" web web/pkg gyrodrift \
    "--merge-similar-functions -Oz --flatten --rereloop -Oz --flatten --rereloop -Oz -Oz --converge" minify
  wasm_part "--no-default-features --features plot" web web/pkg/plot gyrodrift_plot "-Oz --converge" minify
  # Everything: the Web Worker's module (import, tuning, parsing with progress) and Node's;
  # saving a live estimator's state (`snapshot`, 20.5 KB gzipped of serde code) in Node only.
  wasm_part "--no-default-features --features core,import,plot,tune,sim,live" web web/pkg/full gyrodrift "-Oz --converge" minify
  wasm_part "" nodejs web/pkg/node gyrodrift
  cp wasm/npm/package.json wasm/npm/README.md web/pkg/
  printf '{ "type": "commonjs" }\n' > web/pkg/node/package.json
  # The tests and the Node example import the package by its name, as users do.
  mkdir -p tests/node_modules examples/node/node_modules
  ln -sfn ../../web/pkg tests/node_modules/gyrodrift
  ln -sfn ../../../web/pkg examples/node/node_modules/gyrodrift
  # web/ is a static site on its own (any host, any sub-path): the sample logs the page
  # opens are copied in beside it.
  rm -rf web/sample-logs
  mkdir -p web/sample-logs
  cp -r sample-logs/train sample-logs/test sample-logs/robot sample-logs/turntable sample-logs/static web/sample-logs/
}

build_cli() {
  say "building the CLI"
  cargo build --release -p gyrodrift-cli
}
