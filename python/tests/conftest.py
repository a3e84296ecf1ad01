"""Shared fixtures: the repository's sample logs and the CLI built beside the wheel (the
Python results must equal the CLI's ``--json``)."""

import json
import os
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
SAMPLES = ROOT / "sample-logs"
SHARED = ROOT.parent / "shared" / "real-logs"


def cli_path() -> Path:
    return Path(os.environ.get("GYRODRIFT_CLI", ROOT / "target" / "release" / "gyrodrift"))


@pytest.fixture(scope="session")
def cli():
    path = cli_path()
    if not path.exists():
        pytest.fail(f"{path}: build the CLI first (cargo build --release -p gyrodrift-cli)")

    def run(*args: str):
        out = subprocess.run([str(path), *args], capture_output=True, text=True, check=True)
        return json.loads(out.stdout) if "--json" in args else out.stdout

    return run


@pytest.fixture(scope="session")
def samples() -> Path:
    return SAMPLES
