"""The type stubs check with mypy: a typed user's code passes --strict, and a wrong call is
caught (so the stubs are what mypy reads)."""

import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).parent


def mypy(*args: str) -> subprocess.CompletedProcess:
    cache = HERE.parents[1] / "target" / "mypy-cache"
    return subprocess.run([sys.executable, "-m", "mypy", "--cache-dir", str(cache), *args], capture_output=True, text=True)


def test_typed_usage_passes_strict():
    r = mypy("--strict", str(HERE / "typed_usage.py"))
    assert r.returncode == 0, r.stdout + r.stderr


def test_the_package_itself_checks():
    r = mypy("--ignore-missing-imports", "-p", "gyrodrift")
    assert r.returncode == 0, r.stdout + r.stderr


def test_a_wrong_call_is_caught(tmp_path):
    bad = tmp_path / "bad.py"
    bad.write_text("import gyrodrift as g\ng.hdr(123)\nx: str = g.read_log('a.csv').duration_min\n")
    r = mypy("--strict", str(bad))
    assert r.returncode == 1 and 'Argument 1 to "hdr" has incompatible type "int"' in r.stdout, r.stdout
    assert 'Incompatible types in assignment (expression has type "float", variable has type "str")' in r.stdout
