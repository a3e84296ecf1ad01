"""Every method through Python equals the CLI's --json; arrays are float64 numpy; errors
are Python exceptions naming file, line and column."""

import csv
import math

import numpy as np
import pytest

import gyrodrift as g


def close(a, b):
    """Same keys and values (floats to 1e-12 relative: the same core, the same numbers)."""
    if isinstance(a, dict):
        assert set(a) == set(b), (sorted(a), sorted(b))
        for k in a:
            close(a[k], b[k])
    elif isinstance(a, list):
        assert len(a) == len(b)
        for x, y in zip(a, b):
            close(x, y)
    elif isinstance(a, float) or isinstance(b, float):
        assert a == pytest.approx(b, rel=1e-12, abs=1e-12)
    else:
        assert a == b


def test_hdr_pipeline_report_equal_the_cli(cli, samples):
    city = str(samples / "train" / "city-1.csv")
    log = g.read_log(city)
    assert len(log) == 11641 and log.name == "City 1" and log.kind == "drive"
    close(g.hdr(log), cli("hdr", city, "--json"))
    close(g.hdr(log, {"tau_s": 1.0}), cli("hdr", city, "--set", "tau=1.0", "--json"))
    close(g.pipeline(log), cli("pipeline", city, "--json"))
    logs = [g.read_log(str(p)) for p in sorted((samples / "train").glob("*.csv"))]
    files = [str(p) for p in sorted((samples / "train").glob("*.csv"))]
    close(g.report(logs), cli("report", *files, "--json"))
    close(g.compare(logs), cli("report", "--compare", *files, "--json"))
    assert g.table(logs, "report", "markdown") == cli("report", "--markdown", *files)
    assert g.table(logs, "compare", "csv") == cli("report", "--compare", "--csv", *files)


def test_battery_on_a_users_drive_equals_the_clis_battery_logs(cli, samples):
    """Each case's NE_psi per method as the CLI's ``battery --logs`` (whose seventh column,
    the tuned-HDR peer, Python has not: it is tuned on the battery's training bases)."""
    city = str(samples / "test" / "city-3.csv")
    log = g.read_log(city)
    b = g.battery([log])
    native = cli("battery", "--logs", city, "--minutes", "2", "--split", "scoring", "--json")
    mine = [c for c in native["cases"] if c["base"] == log.name]
    assert len(mine) > 20 and len(b["cases"]) == len(mine)
    assert b["methods"] == native["methods"][:6]
    assert b["added"]["n_cases"] == len(mine) and b["training"] is None
    for c, n in zip(b["cases"], mine):
        assert c["profile"] == n["profile"] and not c["training"]
        close(c["ne_psi"], n["ne_psi"][:6])
    with pytest.raises(ValueError, match="ref_heading_deg"):
        g.battery([g.Log.parse("time_s,gyro_dps\n0,0.1\n1,0.1\n2,0.1\n")])


def test_robot_turntable_and_static_methods_equal_the_cli(cli, samples):
    square = str(samples / "robot" / "square.csv")
    close(g.gyrodometry(g.read_log(square)), cli("gyrodometry", square, "--json"))
    session = str(samples / "turntable" / "session.csv")
    close(g.calibrate(g.read_log(session)), cli("calibrate", session, "--json"))
    static = str(samples / "static" / "static-2h.csv")
    a = g.allan(g.read_log(static))
    want = cli("allan", static, "--json")
    arrays = ("tau_s", "adev_dps", "confidence")
    close({k: v for k, v in a.items() if k not in arrays}, {k: v for k, v in want.items() if k not in arrays})
    # the confidence band beside the Result keys (the wasm package's too: test_three_fronts;
    # the CLI prints it in its text table, its --json keeps the Result keys)
    conf = a["confidence"]
    assert isinstance(conf["adev_low_dps"], np.ndarray) and conf["adev_low_dps"].dtype == np.float64
    assert (conf["adev_low_dps"] < a["adev_dps"]).all() and (a["adev_dps"] < conf["adev_high_dps"]).all()
    assert conf["tau_min_range_s"][0] <= a["tau_at_min_s"] <= conf["tau_min_range_s"][1]
    assert isinstance(a["tau_s"], np.ndarray) and a["tau_s"].dtype == np.float64
    np.testing.assert_allclose(a["adev_dps"], want["adev_dps"], rtol=1e-12)
    taus, adev = g.oadev(g.read_log(static))
    np.testing.assert_array_equal(taus, a["tau_s"])
    np.testing.assert_array_equal(adev, a["adev_dps"])


def test_tune_and_check_equal_the_cli(cli, samples):
    files = [str(p) for p in sorted((samples / "train").glob("*.csv"))]
    close(g.tune([g.read_log(f) for f in files]), cli("tune", "--train", *files, "--json"))
    close(g.check(g.read_log(files[0])), cli("check", files[0], "--json"))


def test_runs_give_float64_series_of_one_length(samples):
    log = g.read_log(str(samples / "train" / "city-1.csv"))
    run = g.run_hdr(log)
    assert run["error"] is None and run["result"]["improvement"] > 1
    lengths = {len(v) for v in run["trace"].values()}
    assert len(lengths) == 1 and all(v.dtype == np.float64 for v in run["trace"].values())
    p = g.run_pipeline(log)
    assert p["still_source"] == "speed" and len({len(v) for v in p["trace"].values()}) == 1
    r = g.run_gyrodometry(g.read_log(str(samples / "robot" / "square.csv")))
    assert set(r["trace"]) == {"time_s", "heading_odo_deg", "heading_gyro_deg", "heading_gyrodometry_deg", "used_gyro"}


def test_run_pipeline_trace_equals_the_clis_pipeline_trace(cli, samples, tmp_path):
    """The per-block trace, the causal heading's sigma from the bias model included."""
    city = str(samples / "train" / "city-1.csv")
    out = tmp_path / "trace.csv"
    cli("pipeline", city, "--trace", str(out))
    native = np.genfromtxt(out, delimiter=",", names=True)
    t = g.run_pipeline(g.read_log(city))["trace"]
    for name in ("time_s", "heading_deg", "heading_sigma_deg", "heading_smoothed_deg"):
        assert np.array_equal(t[name], native[name]), name
    assert np.all(t["heading_sigma_deg"] >= 0)


def _stream_equals_run(est, log, v):
    """Feeds the log's rows (speeds `v`) to `est` and checks every closed 1 s block's heading
    (less the alignment), bias, heading sigma and stop against run_pipeline's trace;
    returns the headings and the blocks' states."""
    t, w = log.column("time_s"), log.column("gyro_dps")
    tr = g.run_pipeline(log)["trace"]
    k = np.floor(t - t[0])
    psi, blocks = [], []
    for i in range(len(t)):
        psi.append(est.update(t[i], w[i], v[i]))
        if i > 0 and k[i] != k[i - 1]:
            blocks.append(est.state())
    assert len(blocks) == len(tr["time_s"]) - 1
    shift = tr["heading_deg"][0]
    for j, s in enumerate(blocks):
        assert s["heading_deg"] + shift == tr["heading_deg"][j], j
        assert s["bias_dps"] == tr["bias_dps"][j] and s["heading_sigma_deg"] == tr["heading_sigma_deg"][j]
        assert s["stop"] == bool(tr["stop"][j]), j
    return psi, blocks


def test_pipeline_estimator_streams_run_pipelines_blocks(samples):
    """Rows one by one: each closed 1 s block's heading (less the alignment), bias and
    heading sigma are run_pipeline's; update_many gives the same headings."""
    log = g.read_log(str(samples / "train" / "city-1.csv"))
    t, w, v = (log.column(c) for c in ("time_s", "gyro_dps", "speed_mps"))
    est = g.PipelineEstimator()
    psi, _ = _stream_equals_run(est, log, v)
    assert np.array_equal(g.PipelineEstimator().update_many(t, w, v), np.array(psi))
    with pytest.raises(ValueError, match="time must be finite and increase"):
        est.update(t[0], 0.0, 0.0)
    with pytest.raises(ValueError, match="differ in length"):
        est.update_many(t[:2], w[:1], v[:2])


def test_pipeline_estimator_without_speed_judges_stops_by_the_gyro(samples):
    """Rows without speed: the stream judges stops by the gyro against the lead-in, as the
    batch pipeline does for a log without a speed column, block for block."""
    df = g.to_pandas(g.read_log(str(samples / "train" / "city-1.csv")))[["time_s", "gyro_dps", "ref_heading_deg"]]
    log = g.from_pandas(df, {"name": "City 1, gyro only", "bias_s": 20})
    assert g.run_pipeline(log)["still_source"] == "gyro"
    _, blocks = _stream_equals_run(g.PipelineEstimator({"bias_s": 20}), log, np.full(len(log), np.nan))
    assert sum(s["stop"] for s in blocks) > 30


def test_a_saved_estimator_resumes_where_it_stopped_bit_for_bit(samples):
    """Each live estimator saved halfway (save_state, or pickled) and resumed gives the
    headings and state the uninterrupted one gives; foreign bytes are refused."""
    import pickle

    log = g.read_log(str(samples / "train" / "city-1.csv"))
    t, w, v = (log.column(c) for c in ("time_s", "gyro_dps", "speed_mps"))
    robot = g.read_log(str(samples / "robot" / "square.csv"))
    rt, rw, left, right = (robot.column(c) for c in ("time_s", "gyro_dps", "odo_left_m", "odo_right_m"))
    half, rhalf = len(t) // 2, len(rt) // 2
    cases = [
        (lambda: g.PipelineEstimator({"bias_s": 20}), lambda e, i: e.update(t[i], w[i], v[i]), len(t), half),
        (lambda: g.HdrEstimator(None, g.static_bias(log)), lambda e, i: e.update(t[i], w[i]), len(t), half),
        (lambda: g.GyrodometryEstimator(0.5, 1.0), lambda e, i: e.update(rt[i], rw[i], left[i], right[i]), len(rt), rhalf),
    ]
    for make, step, n, cut in cases:
        whole = make()
        full = [step(whole, i) for i in range(n)]
        for resume in (lambda e: type(e).from_state(e.save_state()), lambda e: pickle.loads(pickle.dumps(e))):
            first = make()
            head = [step(first, i) for i in range(cut)]
            second = resume(first)
            assert second.state() == first.state() and second.heading_deg == first.heading_deg
            tail = [step(second, i) for i in range(cut, n)]
            assert head + tail == full, type(whole).__name__
            assert second.state() == whole.state()
    with pytest.raises(ValueError, match="not a saved gyrodrift state"):
        g.PipelineEstimator.from_state(b"time_s,gyro_dps")
    with pytest.raises(ValueError, match="the state is a PipelineEstimator's"):
        g.HdrEstimator.from_state(g.PipelineEstimator().save_state())


def test_array_arguments_take_what_numpy_reads_as_a_1d_array_of_numbers(samples):
    """update_many and Log.from_columns take lists, pandas Series, strided views and other
    dtypes (numpy.asarray(x, float64)), with the float64 arrays' results; anything else is a
    ValueError naming the argument. Settings take numpy's scalars, and None as the default."""
    log = g.read_log(str(samples / "train" / "city-1.csv"))
    df = g.to_pandas(log)
    t, w, v = (log.column(c) for c in ("time_s", "gyro_dps", "speed_mps"))
    want = g.PipelineEstimator().update_many(t, w, v)
    for args in ((df["time_s"], df["gyro_dps"], df["speed_mps"]), (list(t), list(w), list(v))):
        assert np.array_equal(g.PipelineEstimator().update_many(*args), want)
    half = g.HdrEstimator().update_many(t[::2].copy(), w[::2].copy())
    assert np.array_equal(g.HdrEstimator().update_many(t[::2], w[::2]), half)  # a strided view
    ints = np.arange(100)
    assert np.array_equal(g.HdrEstimator().update_many(ints, ints % 7), g.HdrEstimator().update_many(ints.astype(float), (ints % 7).astype(float)))
    cols = g.Log.from_columns({"time_s": list(t[:50]), "gyro_dps": w[:100:2], "speed_mps": df["speed_mps"][:50]})
    assert np.array_equal(cols.column("gyro_dps"), w[:100:2])
    for bad in ("abc", [[1.0, 2.0], [3.0, 4.0]], ["x", "y"], None):
        with pytest.raises(ValueError, match="time_s: expected a 1-d array of numbers"):
            g.HdrEstimator().update_many(bad, [0.0, 1.0])
    # A setting given as None takes its default (nested ones too), as a keyword argument's.
    assert g.hdr(log, {"tau_s": None, "bias_s": None}) == g.hdr(log)
    assert g.pipeline(log, {"still": {"still_speed_mps": None}, "road_gate_dps": None}) == g.pipeline(log)
    # Settings take numpy's scalars as Python's: a numpy bool is a bool, not the number 1.
    assert g.hdr(log, {"resample": np.bool_(False), "tau_s": np.float32(1.0), "bias_s": np.int64(20)}) == g.hdr(log, {"resample": False, "tau_s": 1.0, "bias_s": 20})


def test_a_log_with_a_check_error_is_refused_by_the_tables_as_the_cli_refuses_it(cli, samples, tmp_path):
    """A clockwise gyro (every rate negated): the tables raise naming the log, the finding and
    the fix, as the CLI exits; ignore_check=True runs it, equal to the CLI's --ignore-check."""
    city = g.read_log(str(samples / "train" / "city-1.csv"))
    df = g.to_pandas(city)
    df["gyro_dps"] = -df["gyro_dps"]
    cw = g.from_pandas(df, {"name": "City 1 clockwise", "bias_s": 20})
    refused = r"City 1 clockwise: check: error \[gyro_sign\].*ignore_check=True runs it anyway"
    for table in (g.report, g.compare, g.battery, lambda logs, **k: g.table(logs, "compare", "csv", **k),
                  lambda logs, **k: g.tune(logs, [city], **k)):
        with pytest.raises(ValueError, match=refused) as e:
            table([city, cw])
        assert (e.value.code, e.value.log) == ("check", "City 1 clockwise")
    path = tmp_path / "cw.csv"
    path.write_text(cw.to_csv())
    close(g.report([cw], ignore_check=True), cli("report", str(path), "--ignore-check", "--json"))
    close(g.compare([cw], ignore_check=True), cli("report", "--compare", str(path), "--ignore-check", "--json"))


def test_a_log_without_reference_runs_but_has_no_result(samples):
    run = g.run_hdr(g.read_log(str(samples / "static" / "static-2h.csv")))
    assert run["result"] is None and "ref_heading_deg" in run["error"]
    with pytest.raises(ValueError, match="ref_heading_deg"):
        g.hdr(g.read_log(str(samples / "static" / "static-2h.csv")))


def test_a_drive_without_reference_gets_the_clis_summary(cli, samples, tmp_path):
    """A drive with speed and no GPS course: a drive, not scored, and its summary (bias,
    heading turned) is the CLI's unscored JSON, key for key."""
    df = g.to_pandas(g.read_log(str(samples / "train" / "city-1.csv")))[["time_s", "gyro_dps", "speed_mps"]]
    log = g.from_pandas(df, {"name": "City 1 without GPS", "bias_s": 20})
    assert log.kind == "drive" and not log.has_reference
    assert g.read_log(str(samples / "train" / "city-1.csv")).has_reference
    # Tables over drives leave it out with a warning naming it, as the CLI does on stderr;
    # with no drive left to score they raise.
    city = g.read_log(str(samples / "train" / "city-1.csv"))
    for table in (g.report, g.compare, lambda logs: g.table(logs, "compare", "csv")):
        with pytest.warns(UserWarning, match="City 1 without GPS: not scored: no reference heading"):
            assert table([log, city]) == table([city])
    with pytest.warns(UserWarning, match="City 1 without GPS"):
        assert g.tune([city, log], [city])["train"] == g.tune([city], [city])["train"]
    with pytest.raises(ValueError, match=r"no drive has a reference heading to score against \(City 1 without GPS\)"), pytest.warns(UserWarning):
        g.report([log])
    path = tmp_path / "no-gps.csv"
    path.write_text(log.to_csv())
    for run, command in ((g.run_pipeline(log), "pipeline"), (g.run_hdr(log), "hdr")):
        assert run["result"] is None and "ref_heading_deg" in run["error"]
        native = cli(command, str(path), "--json")
        assert native.pop("not_scored") == run["error"]
        assert run["summary"].keys() == native.keys(), command
        for k, v in native.items():
            assert run["summary"][k] == (v if isinstance(v, str) else pytest.approx(v, rel=1e-12)), (command, k)
    # The fleet's row of it: not an error, not scored, the same figures.
    (row,) = g.score_file(str(path))
    assert row["error"] is None and "ref_heading_deg" in row["not_scored"] and row["ne_psi_raw_deg_per_min"] is None
    summary = g.run_pipeline(log)["summary"]
    for k in ("heading_change_deg", "heading_change_sigma_deg", "heading_change_smoothed_deg", "final_bias_dps", "final_bias_sigma_dps", "stop_s"):
        assert row["pipeline_" + k] == pytest.approx(summary[k], rel=1e-12), k
    assert g.summarize([row])["not_scored"] == 1
    # Scored or not, the pipeline's summary is its result's end figures.
    scored = g.run_pipeline(g.read_log(str(samples / "train" / "city-1.csv")))
    assert scored["summary"]["final_bias_dps"] == scored["result"]["final_bias_dps"]
    assert scored["summary"]["stop_s"] == scored["result"]["stop_s"]


def test_pandas_round_trip_scores_the_same(samples):
    log = g.read_log(str(samples / "train" / "city-1.csv"))
    df = g.to_pandas(log)
    assert list(df.columns) == log.column_names() and len(df) == len(log)
    df["unrelated"] = "x"  # ignored
    back = g.from_pandas(df, {"name": "City 1", "bias_s": 20})
    assert back.name == "City 1"
    assert g.hdr(back) == g.hdr(log)
    np.testing.assert_array_equal(back.column("gyro_dps"), log.column("gyro_dps"))


def _same_log(a, b):
    """Equal in every value (NaN cells where the other has them) and in metadata."""
    assert (a.meta(), a.column_names(), len(a)) == (b.meta(), b.column_names(), len(b))
    for name in a.column_names():
        np.testing.assert_array_equal(a.column(name), b.column(name))
    assert a.to_csv() == b.to_csv()


def test_a_log_pickles_and_copies_with_its_values_and_metadata(samples, tmp_path):
    import copy
    import pickle

    # Metadata of every kind (name, bias_s, a key of the user's own) and empty cells.
    text = "# name: mine\n# bias_s: 2.5\n# vehicle: van 7\ntime_s,gyro_dps,ref_heading_deg,speed_mps\n"
    text += "".join(f"{i * 0.1:.1f},{0.1 * (i % 7) - 0.3},{'' if i % 3 else i * 0.01},{'' if i % 5 == 1 else 3}\n" for i in range(200))
    logs = [g.Log.parse(text)] + [g.read_log(str(p)) for p in sorted(samples.glob("*/*.csv"))]
    for log in logs:
        for back in (pickle.loads(pickle.dumps(log, protocol=p)) for p in (2, pickle.HIGHEST_PROTOCOL)):
            _same_log(back, log)
        _same_log(copy.deepcopy(log), log)
    # A log put in time order as it was read comes back as it is.
    late = tmp_path / "late.csv"
    late.write_text("# bias_s: 0\n\ntime_s,gyro_dps\n" + "".join(f"{t},{t / 10}\n" for t in (0, 1, 3, 2, 4)))
    with pytest.warns(UserWarning, match="1 late rows put in time order"):
        fixed = g.read_log(str(late), time_order="fix")
    _same_log(pickle.loads(pickle.dumps(fixed)), fixed)
    # Metadata floats come back exactly (through JSON text a sixth of them moved by a bit).
    biases = [0.1 * k + 1e-13 * k * k for k in range(1, 300)]
    for b in biases:
        one = g.Log.from_columns({"time_s": [0.0, 1.0], "gyro_dps": [0.0, 0.0]}, {"bias_s": b, "wheelbase_m": b / 7})
        assert pickle.loads(pickle.dumps(one)).meta() == one.meta()
    assert g.hdr(pickle.loads(pickle.dumps(logs[1]))) == g.hdr(logs[1])


def test_logs_cross_processes_as_a_fleet_job_passes_them(samples):
    """A process pool and Dask's process scheduler return Logs to the caller (pickled)."""
    from concurrent.futures import ProcessPoolExecutor

    import dask.bag as db

    paths = [str(p) for p in sorted((samples / "train").glob("*.csv"))[:3]]
    with ProcessPoolExecutor(2) as pool:
        logs = list(pool.map(g.read_log, paths))
    bag = db.from_sequence(paths, npartitions=3).map(g.read_log)
    from_dask = bag.compute(scheduler="processes", num_workers=2)
    for a, b, p in zip(logs, from_dask, paths):
        _same_log(a, g.read_log(p))
        _same_log(b, g.read_log(p))
    assert [g.pipeline(x) for x in logs] == [g.pipeline(g.read_log(p)) for p in paths]


def test_a_frame_indexed_by_time_makes_the_log_its_seconds_would(samples):
    """A DataFrame without time_s whose index is date-times (time zone and all) or time spans,
    or whose time_s column is date-times: the log of its seconds (date-times since the
    first row), scoring as the file does."""
    import pandas as pd

    log = g.read_log(str(samples / "train" / "city-1.csv"))
    df = g.to_pandas(log)
    t = df.pop("time_s")
    start = pd.Timestamp("2024-05-01 07:30", tz="Europe/Berlin")
    stamps = start + pd.to_timedelta(t - t.iloc[0], unit="s")
    meta = {"bias_s": 20}
    want = g.hdr(g.from_pandas(df.assign(time_s=t - t.iloc[0]), meta))
    for frame in (df.set_index(pd.DatetimeIndex(stamps)), df.set_index(pd.TimedeltaIndex(pd.to_timedelta(t - t.iloc[0], unit="s"))), df.assign(time_s=stamps)):
        back = g.from_pandas(frame, meta)
        np.testing.assert_allclose(back.column("time_s"), t - t.iloc[0], rtol=0, atol=1e-9)
        got = g.hdr(back)
        assert abs(got["E_psi_hdr_deg"] - want["E_psi_hdr_deg"]) < 1e-6, (got, want)
    with pytest.raises(ValueError, match="missing column time_s"):
        g.from_pandas(df)  # a plain index is not a time


def test_streaming_hdr_equals_the_batch_on_rows(samples):
    log = g.read_log(str(samples / "train" / "city-1.csv"))
    eps0 = g.static_bias(log)
    run = g.run_hdr(log, {"resample": False})
    t, w = log.column("time_s"), log.column("gyro_dps")
    est = g.HdrEstimator(None, eps0)
    psi = est.update_many(t, w)
    # The batch heading is shifted to the first reference value: the same up to a constant.
    d = run["trace"]["heading_hdr_deg"] - psi
    assert np.ptp(d) < 1e-9
    one = g.HdrEstimator(None, eps0)
    assert [one.update(a, b) for a, b in zip(t[:50], w[:50])] == pytest.approx(list(psi[:50]), abs=1e-12)
    assert one.state()["heading_deg"] == one.heading_deg
    with pytest.raises(ValueError, match="not after the previous"):
        one.update(t[10], 0.0)
    gy = g.GyrodometryEstimator(0.5, 0.5)
    assert math.isfinite(gy.update(0.0, 0.0, 0.0, 0.0)) and gy.state() is not None


def test_simulate_equals_the_cli(cli):
    log = g.simulate({"kind": "drive", "scenario": "city", "minutes": 3, "seed": 7})
    assert log.to_csv() == cli("simulate", "drive", "--scenario", "city", "--minutes", "3", "--seed", "7")


def test_gyro_errors_equal_the_clis_inject_and_simulate(cli, samples):
    file = str(samples / "test" / "city-3.csv")
    log = g.read_log(file)
    before = log.to_csv()
    mems = next(p for p in g.battery_profiles() if p["name"] == "cheap MEMS A cut")
    assert mems["training"] and mems["errors"]["cut_lead_in"] is True
    worse = g.add_gyro_errors(log, {**mems["errors"], "seed": 4})
    assert worse.to_csv() == cli("inject", file, "--profile", "cheap MEMS A cut", "--error", "seed=4")
    sim = g.simulate({"kind": "drive", "scenario": "rural", "minutes": 2, "seed": 3, "errors": {"bias_dps": -1.5, "gyro_only": True}})
    assert sim.to_csv() == cli(
        "simulate", "drive", "--scenario", "rural", "--minutes", "2", "--seed", "3", "--error", "bias_dps=-1.5", "--error", "gyro_only=1"
    )
    with pytest.raises(ValueError, match="noise_dps"):
        g.add_gyro_errors(log, {"noise_dps": -1})
    with pytest.raises(ValueError, match="bias"):
        g.add_gyro_errors(log, {"bias": 1})
    assert log.to_csv() == before


def test_bad_input_raises_with_file_line_and_column(tmp_path):
    bad = tmp_path / "bad.csv"
    bad.write_text("time_s,gyro_dps,ref_heading_deg\n0,0.1,0\n1,abc,0\n")
    with pytest.raises(ValueError, match=r"bad\.csv: line 3, column gyro_dps"):
        g.read_log(str(bad))
    with pytest.raises(OSError, match="cannot open"):
        g.read_log(str(tmp_path / "missing.csv"))
    with pytest.raises(ValueError, match="line 3"):
        g.Log.parse("time_s,gyro_dps\n0,1\n0,nan\n")
    log = g.Log.parse("time_s,gyro_dps,ref_heading_deg\n" + "".join(f"{i},0.1,0\n" for i in range(100)))
    with pytest.raises(ValueError, match="tau"):
        g.hdr(log, {"tau_s": -1})
    with pytest.raises(ValueError, match="unknown field"):
        g.hdr(log, {"tua_s": 1})
    with pytest.raises(ValueError, match="finite"):
        g.hdr(log, {"tau_s": float("nan")})
    with pytest.raises(TypeError):
        g.hdr(log, {"tau_s": object()})
    with pytest.raises(KeyError):
        g.Log.from_columns({"time_z": np.zeros(3)})
    with pytest.raises(ValueError, match="time_s: expected a 1-d array of numbers"):
        g.Log.from_columns({"time_s": np.array(["0", "x", "2"])})
    with pytest.raises(ValueError):
        g.Log.from_columns({"time_s": np.array([0.0, 1.0, 0.5]), "gyro_dps": np.zeros(3)})


@pytest.mark.skipif(not (__import__("conftest").SHARED / "comma2k19-example").exists(), reason="../shared/real-logs not beside the repo")
def test_import_by_recipe_equals_the_cli(cli, samples, tmp_path):
    from conftest import SHARED

    recipe = str(samples / "recipes" / "comma2k19-example.toml")
    log, summary = g.import_log(recipe, str(SHARED))
    out = tmp_path / "c.csv"
    cli("import", "--recipe", recipe, "--data", str(SHARED), "--out", str(out))
    assert log.to_csv() == out.read_text()
    assert summary["n_rows"] == len(log)
    with pytest.raises(ValueError, match="refused"):
        import tomllib

        bad = tomllib.loads(open(recipe).read())
        bad["table"][0]["file"] = "../../etc/passwd"
        g.import_log(bad, str(SHARED))


def test_import_files_detects_the_preset_and_equals_the_cli(cli, samples, tmp_path):
    folder = samples / "wild" / "phyphox"
    paths = sorted(str(p) for p in folder.iterdir())
    log, summary, detection = g.import_files(paths)
    assert detection["preset"] == "phyphox"
    assert [u[0] for u in detection["used"]] == ["gyro", "acc", "location"]
    assert detection["recipe"]["table"][0]["delimiter"] == ";"
    out = tmp_path / "p.csv"
    cli("import", *paths, "--out", str(out))
    assert log.to_csv() == out.read_text()
    assert summary["n_reference"] > 20
    odd = tmp_path / "odd.csv"
    odd.write_text("alpha;beta\n1;2\n")
    with pytest.raises(ValueError, match="no logger preset .*odd.csv"):
        g.import_files([str(odd)])


def test_draft_recipe_from_column_names_imports_as_the_cli_prints_it(cli, tmp_path):
    mine = tmp_path / "my-logger.csv"
    mine.write_text("stamp_ms,gyro_z_dps,course,speed_kmh\n0,1,,0\n1000,2,10,36\n2000,3,20,3.6\n")
    d = g.draft_recipe([str(mine)])
    assert d["recipe"]["table"][0]["time"] == {"column": "stamp_ms", "unit": "ms"}
    assert any(x.startswith('yaw_rate: my-logger.csv column "gyro_z_dps", deg/s') for x in d["guesses"])
    log, summary = g.import_log(d["recipe"], str(tmp_path))
    assert list(log.column("gyro_dps")) == [1.0, 2.0, 3.0]
    assert summary["n_reference"] == 1  # 36 km/h passes the draft's 5 m/s, 3.6 does not
    printed = tmp_path / "draft.toml"
    printed.write_text(cli("import", str(mine), "--print-recipe"))
    log2, _ = g.import_log(str(printed), str(tmp_path))
    assert log2.to_csv() == log.to_csv()
    bad = tmp_path / "c.csv"
    bad.write_text("t,a,b\n")
    with pytest.raises(ValueError, match="no column reads as a yaw rate"):
        g.draft_recipe([str(bad)])


def test_column_guesses_read_each_column_as_the_draft_does(tmp_path):
    imu = tmp_path / "imu.csv"
    imu.write_text("time,gyro_x,gyro_y,gyro_z,accel_x,accel_y,accel_z\n0,0,0,-0.2,0,0,-9.81\n")
    gps = tmp_path / "gps.csv"
    gps.write_text("time,lat,lon,speed_kmh\n0,42,11,36\n")
    guesses = g.column_guesses([str(imu), str(gps)])
    assert [f["name"] for f in guesses["files"]] == ["imu.csv", "gps.csv"]  # the paths' order
    assert guesses["yaw_rate"] == {"file": 0, "column": "gyro_z"}
    assert guesses["yaw_from_axes"] is True
    assert guesses["lat_lon"] == {"file": 1, "lat": "lat", "lon": "lon"}
    speed = next(c for c in guesses["files"][1]["columns"] if c["name"] == "speed_kmh")
    assert speed["speed_unit"] == "km/h"
    assert g.draft_recipe([str(imu), str(gps)])["recipe"]["yaw_rate"]["axes"] == ["gyro_x", "gyro_y", "gyro_z"]
    with pytest.raises(ValueError, match="a folder among files"):
        g.column_guesses([str(imu), str(tmp_path)])


def test_the_type_stubs_name_exactly_what_the_module_has():
    import ast
    import pathlib

    import gyrodrift._core as core

    stub = ast.parse((pathlib.Path(g.__file__).parent / "_core.pyi").read_text())
    top = {n.name for n in stub.body if isinstance(n, (ast.FunctionDef, ast.ClassDef))}
    top |= {t.target.id for t in stub.body if isinstance(t, ast.AnnAssign)}
    public = {n for n in dir(core) if not n.startswith("_")}
    assert top == public
    assert public <= set(g.__all__), public - set(g.__all__)
    for cls in (n for n in stub.body if isinstance(n, ast.ClassDef)):
        methods = {m.name for m in cls.body if isinstance(m, ast.FunctionDef) and not m.name.startswith("__")}
        have = {n for n in dir(getattr(core, cls.name)) if not n.startswith("_")}
        assert methods == have, cls.name


def test_import_refuses_a_link_out_of_the_data_folder(tmp_path):
    # As the CLI does: a table file that is a link leading outside data_dir is refused
    # before it is read (its content never reaches the message).
    outside = tmp_path / "outside.csv"
    outside.write_text("t,z\nSECRET,1\n")
    data = tmp_path / "data"
    data.mkdir()
    (data / "g.csv").symlink_to(outside)
    recipe = {
        "table": [{"id": "g", "file": "g.csv", "time": {"column": "t", "unit": "s"}}],
        "yaw_rate": {"table": "g", "column": "z", "unit": "deg/s", "positive": "ccw"},
    }
    with pytest.raises(ValueError, match="refused: a link leads out of the data folder") as e:
        g.import_log(recipe, str(data))
    assert "SECRET" not in str(e.value)


def test_a_raw_export_read_as_a_log_names_the_import_that_reads_it(samples):
    """read_log on a logger's raw export: the error names the file and line, and the
    import_files call (with the files beside it that the preset uses) that makes a v1 log."""
    folder = samples / "wild" / "px4"
    files = sorted(str(p) for p in folder.iterdir())
    with pytest.raises(ValueError, match=r"line 1: missing required column time_s.*import preset px4") as e:
        g.read_log(files[0])
    assert all(repr(f) in str(e.value) or f'"{f}"' in str(e.value) for f in files), str(e.value)
    log, _, _ = g.import_files(files)
    assert len(log) > 0


def test_a_zipped_export_imports_as_its_files_do(samples, tmp_path):
    """import_files on a ZIP of a recording (as Sensor Logger shares one): the log its files
    give; read_log on it names that import_files call."""
    import zipfile

    folder = samples / "wild" / "sensor-logger"
    files = sorted(folder.iterdir())
    zpath = tmp_path / "drive.zip"
    with zipfile.ZipFile(zpath, "w", zipfile.ZIP_DEFLATED) as z:
        for f in files:
            z.write(f, "Drive/" + f.name)
    log, _, detection = g.import_files([str(zpath)])
    plain, _, _ = g.import_files([str(f) for f in files])
    assert detection["preset"] == "sensor-logger"
    assert np.array_equal(log.column("gyro_dps"), plain.column("gyro_dps"))
    with pytest.raises(ValueError, match=r"a ZIP archive, not a text table.*import preset sensor-logger.*drive\.zip"):
        g.read_log(str(zpath))
    # The detected recipe names the log by the archive, and reads the zip again as its data.
    assert detection["recipe"]["name"] == "drive"
    again, _ = g.import_log(detection["recipe"], str(zpath))
    assert again.name == "drive"
    assert np.array_equal(again.column("gyro_dps"), log.column("gyro_dps"))


def test_import_files_on_a_folder_imports_its_files_named_by_it(samples):
    """import_files([folder]): an unzipped export as its files, named by the folder."""
    folder = samples / "wild" / "sensor-logger"
    log, _, detection = g.import_files([str(folder)])
    plain, _, _ = g.import_files([str(f) for f in sorted(folder.iterdir())])
    assert log.name == "sensor-logger" and detection["recipe"]["name"] == "sensor-logger"
    assert np.array_equal(log.column("gyro_dps"), plain.column("gyro_dps"))


def test_a_folder_read_as_a_log_names_the_import_or_the_fleet_job(samples):
    """read_log on a folder: a ValueError saying so, with the import_files call when a preset
    reads the recording in it, else the fleet job."""
    with pytest.raises(ValueError, match=r"a folder, not a log file; it looks like a recording of .*import preset phyphox") as e:
        g.read_log(str(samples / "wild" / "phyphox"))
    assert "gyrodrift.import_files([" in str(e.value)
    with pytest.raises(ValueError, match=r"a folder, not a log file; to score every log in it: python -m gyrodrift.fleet"):
        g.read_log(str(samples / "train"))


def test_pipeline_track_is_the_clis_track_csv(cli, samples, tmp_path):
    """Every method's dead-reckoned path: the CLI's `pipeline --track` CSV, column for column;
    without a GPS course the same minus the reference's; without a speed a ValueError."""
    path = samples / "train" / "city-1.csv"
    tr = g.pipeline_track(g.read_log(str(path)))
    out = tmp_path / "track.csv"
    cli("pipeline", str(path), "--json", "--track", str(out))
    with out.open() as f:
        rows = list(csv.reader(f))
    header, body = rows[0], rows[1:]
    assert list(tr.keys()) == header
    for j, name in enumerate(header):
        assert tr[name].dtype == np.float64 and len(tr[name]) == len(body), name
        assert np.array_equal(tr[name], np.array([float(r[j]) for r in body])), name
    df = g.to_pandas(g.read_log(str(path)))[["time_s", "gyro_dps", "speed_mps"]]
    unscored = g.pipeline_track(g.from_pandas(df, {"bias_s": 20}))
    assert "reference_x_m" not in unscored and len(unscored["pipeline_x_m"]) == len(body)
    with pytest.raises(ValueError, match="speed_mps"):
        g.pipeline_track(g.from_pandas(df[["time_s", "gyro_dps"]].assign(ref_heading_deg=0.0)))
