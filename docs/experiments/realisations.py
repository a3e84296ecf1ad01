"""The 16 realisations of the shipped sets for the experiment scripts: `gyrodrift samples
--realisation K` into OUT/realisation-K (written when missing), each set's drives scored by
`report --compare --json`."""
import json
import subprocess
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent.parent


def rows(cli, out, part):
    """Every drive of one set ("train" or "test") over the 16 realisations: `report
    --compare --json`'s rows (name and every method's NE_psi), realisation by realisation.
    The CLI runs from the repository's root with this process's environment."""
    found = []
    for k in range(16):
        folder = Path(out) / f"realisation-{k}"
        if not (folder / part).is_dir():
            subprocess.run([cli, "samples", "--out", str(folder), "--realisation", str(k)], cwd=ROOT, check=True, capture_output=True)
        logs = sorted(str(p) for p in (folder / part).glob("*.csv"))
        text = subprocess.run([cli, "report", "--compare", "--json", *logs], cwd=ROOT, check=True, capture_output=True, text=True).stdout
        found += json.loads(text)["rows"]
    return found
