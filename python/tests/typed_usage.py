"""What a typed user writes; checked by mypy --strict against the package's stubs
(test_types.py). Not a test module itself."""

from typing import Any, Dict, List

import numpy as np
import numpy.typing as npt

import gyrodrift as g


def heading_errors(path: str) -> float:
    log: g.Log = g.read_log(path)
    result: Dict[str, Any] = g.hdr(log, {"tau_s": 1.0})
    run = g.run_hdr(log)
    trace: npt.NDArray[np.float64] = run["trace"]["heading_hdr_deg"]
    est = g.HdrEstimator(None, g.static_bias(log))
    psi: npt.NDArray[np.float64] = est.update_many(log.column("time_s"), log.column("gyro_dps"))
    rows: List[Dict[str, Any]] = g.score_files([path], jobs=2)
    taus, adev = g.oadev(log)
    return float(result["NE_psi_hdr_deg_per_min"]) + float(trace[0] + psi[0] + taus[0] + adev[0]) * 0 + len(rows) * 0


def robustness(paths: List[str]) -> int:
    logs = [g.read_log(p) for p in paths]
    b: Dict[str, Any] = g.battery(logs, {"warm_sigma_dps": 0.3})
    return int(b["added"]["n_within"])


def live_heading(path: str) -> float:
    log = g.read_log(path)
    est = g.PipelineEstimator({"bias_s": 20.0})
    psi: npt.NDArray[np.float64] = est.update_many(log.column("time_s"), log.column("gyro_dps"), log.column("speed_mps"))
    state = est.state()
    sigma = float(state["heading_sigma_deg"]) if state is not None else 0.0
    # Rows as plain lists (any array-like numpy reads), and the estimator saved and resumed.
    more: npt.NDArray[np.float64] = est.update_many([1e6], [0.1], [0.0])
    resumed: g.PipelineEstimator = g.PipelineEstimator.from_state(est.save_state())
    return float(psi[-1] + more[0]) * 0 + resumed.heading_deg + sigma * 0


def track_end(path: str) -> float:
    paths = g.pipeline_track(g.read_log(path), {"bias_s": 20.0})
    x: npt.NDArray[np.float64] = paths["pipeline_x_m"]
    return float(x[-1]) + float(paths["time_s"][-1]) * 0
