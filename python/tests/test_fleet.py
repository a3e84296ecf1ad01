"""Fleet rows from Python equal the CLI's `report --dir`; the Dask job (LocalCluster, 2
workers) gives the same rows from a folder of CSV logs and from a Parquet dataset; a bad
drive is a row with its error."""

import json
import os
import re
import shutil
from pathlib import Path

import numpy as np
import pandas as pd
import pyarrow.parquet as pq
import pytest

import gyrodrift as g
from gyrodrift import fleet


@pytest.fixture(scope="module")
def folder(tmp_path_factory, samples):
    d = tmp_path_factory.mktemp("fleet")
    (d / "day2").mkdir()
    for p in sorted((samples / "train").glob("*.csv"))[:3]:
        shutil.copy(p, d / p.name)
    shutil.copy(samples / "test" / "highway-3.csv", d / "day2" / "highway-3.csv")
    (d / "day2" / "broken.csv").write_text("time_s,gyro_dps,ref_heading_deg\n0,0.1,0\n1,abc,0\n")
    # 15 more short simulated drives: 20 files, one of them broken.
    scenarios = ["city", "suburbs", "rural", "highway", "downtown"]
    for seed in range(15):
        log = g.simulate({"kind": "drive", "scenario": scenarios[seed % 5], "minutes": 2, "seed": 100 + seed})
        (d / "sim").mkdir(exist_ok=True)
        (d / "sim" / f"sim-{seed:02}.csv").write_text(log.to_csv())
    return d


def by_file(rows):
    return sorted(rows, key=lambda r: (r["file"], r["part"]))


def test_rows_equal_the_cli_batch(cli, folder, tmp_path):
    out = tmp_path / "rows.json"
    cli("report", "--dir", str(folder), "--out", str(out))
    want = json.loads(out.read_text())
    files = sorted(str(p) for p in folder.rglob("*.csv"))
    got = g.score_files(files, jobs=2)
    assert by_file(got) == by_file(want)
    bad = [r for r in got if r["error"]]
    assert len(bad) == 1 and "line 3, column gyro_dps" in bad[0]["error"] and bad[0]["ne_psi_hdr_deg_per_min"] is None
    assert g.score_file(files[0]) == [r for r in got if r["file"] == files[0]]
    s = g.summarize(got)
    assert (s["files"], s["scored"], s["errors"]) == (20, 19, 1)
    assert g.summary_markdown(got).startswith("20 files, 19 drives scored")


def test_the_cli_parquet_reads_in_pyarrow_with_the_json_values(cli, folder, tmp_path):
    cli("compare", "--dir", str(folder), "--out", str(tmp_path / "rows.parquet"))
    cli("report", "--dir", str(folder), "--out", str(tmp_path / "rows.json"))
    table = pq.read_table(tmp_path / "rows.parquet")
    assert table.column_names == g.row_columns()
    df = table.to_pandas()
    want = pd.DataFrame(json.loads((tmp_path / "rows.json").read_text()), columns=g.row_columns())
    # A text column with no value (not_scored here) reads back as NaN, the JSON's as None.
    none = lambda f: f.astype(object).where(f.notna(), None)  # noqa: E731
    pd.testing.assert_frame_equal(none(df), none(want), check_dtype=False)


def test_dask_on_a_folder_gives_the_rows_and_the_parquet(folder, tmp_path):
    out = tmp_path / "fleet.parquet"
    rows = fleet.run(str(folder), str(out), workers=2, chunk_bytes=1_500_000)
    want = g.rows_to_pandas(g.score_files(sorted(str(p) for p in folder.rglob("*.csv"))))
    key = ["file", "part"]
    # Text columns may come back as object or str dtype after the concat; the values are equal.
    pd.testing.assert_frame_equal(rows.sort_values(key).reset_index(drop=True), want.sort_values(key).reset_index(drop=True), check_dtype=False)
    assert pq.read_table(out).num_rows == len(rows) == 20
    assert "HDR Table III | 19 |" in fleet.summary(rows)


def test_dask_on_a_parquet_dataset_partitioned_by_drive(samples, tmp_path):
    logs = {p.stem: g.read_log(str(p)) for p in sorted((samples / "train").glob("*.csv"))[:2]}
    frames = []
    for key, log in logs.items():
        df = g.to_pandas(log)
        df["drive"] = key
        frames.append(df)
    data = tmp_path / "drives"
    pd.concat(frames).to_parquet(data, partition_cols=["drive"], index=False)
    rows = fleet.run(str(data), workers=2)
    assert sorted(rows["file"]) == sorted(logs)
    for key, log in logs.items():
        r = rows[rows["file"] == key].iloc[0]
        want = g.score_log(g.from_pandas(g.to_pandas(log), {"name": key}), key)[0]
        assert r["ne_psi_pipeline_deg_per_min"] == pytest.approx(want["ne_psi_pipeline_deg_per_min"], rel=1e-12)
        assert r["error"] is None or (isinstance(r["error"], float) and np.isnan(r["error"]))


def test_score_frame_as_spark_applyinpandas_would_call_it(samples):
    log = g.read_log(str(samples / "train" / "city-1.csv"))
    df = g.to_pandas(log).sample(frac=1.0, random_state=1)  # any row order
    df["drive"] = "city-1"
    out = fleet.score_frame(df)
    assert list(out.columns) == g.row_columns() and len(out) == 1
    assert out["ne_psi_hdr_deg_per_min"][0] == pytest.approx(g.hdr(log)["NE_psi_hdr_deg_per_min"], rel=1e-9)
    bad = fleet.score_frame(pd.DataFrame({"drive": ["x"], "time_s": [0.0], "gyro_dps": [np.inf]}))
    assert bad["error"][0]


def test_the_command_line(folder, tmp_path, capsys):
    assert fleet.main([str(folder), "--out", str(tmp_path / "r.parquet"), "--workers", "1"]) == 0
    captured = capsys.readouterr()
    assert captured.out.startswith("20 files, 19 drives scored") and "broken.csv: line 3" in captured.err
    assert fleet.main([str(tmp_path / "nothing-here" / "*.csv")]) == 2
    assert "no file matches" in capsys.readouterr().err
    # A CI job: exit 1 when a file is an error row, the rows written all the same.
    assert fleet.main([str(folder), "--out", str(tmp_path / "r2.parquet"), "--workers", "1", "--fail-on-error"]) == 1
    assert "1 of 20 rows are errors (--fail-on-error)" in capsys.readouterr().err
    assert len(pd.read_parquet(tmp_path / "r2.parquet")) == 20


def test_the_command_line_names_the_option_for_refusals_by_kind(samples, tmp_path, capsys):
    """Files refused for what an option reads are error rows with the refusal's kind in
    ``error_code``, and the fleet job names the option once for them; given, it scores each."""
    city = (samples / "train" / "city-1.csv").read_text()
    head, body = city[: city.index("time_s,")], city[city.index("time_s,") :]
    rows = body.splitlines()
    logs = tmp_path / "logs"
    logs.mkdir()
    (logs / "repeat.csv").write_text(head + "\n".join(rows[:3] + [rows[2]] + rows[3:]) + "\n")
    (logs / "joined.csv").write_text(city + city)
    (logs / "reset.csv").write_text(city + "\n".join(rows[1:]) + "\n")
    (logs / "city.csv").write_text(city)
    cw = [l if l.startswith("#") or l.startswith("time_s") or not l else ",".join([c if j != 1 else repr(-float(c)) for j, c in enumerate(l.split(","))]) for l in city.splitlines()]
    (logs / "cw.csv").write_text("\n".join(cw) + "\n")
    assert fleet.main([str(logs), "--out", str(tmp_path / "r.parquet"), "--workers", "1"]) == 0
    err = capsys.readouterr().err
    assert err.count("""1 file refused for a time that repeats or steps back by at most 1 s: --options '{"input": {"time_order": "fix"}}'""") == 1, err
    assert err.count("""2 files refused for a second log joined on or a clock reset: --options '{"input": {"joined": "split"}}'""") == 1, err
    out = pd.read_parquet(tmp_path / "r.parquet").set_index("file")
    codes = {Path(f).name: (None if pd.isna(c) else c) for f, c in out["error_code"].items()}
    assert err.count("""1 file refused for a unit or sign mistake check found: gyrodrift.check(gyrodrift.read_log(path)) names each fix""") == 1, err
    assert codes == {"city.csv": None, "joined.csv": "joined", "repeat.csv": "time_order", "reset.csv": "clock_reset", "cw.csv": "check"}
    # Core's hints as data, for a job of one's own: kinds counted, why, and the remedy's kind.
    records = json.loads(out.reset_index().to_json(orient="records"))
    hints = [(h["files"], h["remedy"]) for h in g.refusal_hints(records)]
    assert hints == [(1, "time_order_fix"), (2, "joined_split"), (1, "check_each")], hints
    options = '{"input": {"joined": "split", "time_order": "fix", "ignore_check": true}}'
    assert fleet.main([str(logs), "--workers", "1", "--options", options]) == 0
    captured = capsys.readouterr()
    assert captured.out.startswith("5 files, 7 drives scored") and "refused for" not in captured.err, captured


def test_options_as_the_command_line_documents_them(folder):
    # A log with a gap is refused under {"input": {"gaps": "error"}}; a misspelled key is refused.
    rows = g.score_files([str(p) for p in sorted(folder.rglob("city-1.csv"))], options={"input": {"gaps": "error"}})
    assert rows[0]["error"] is None
    with pytest.raises(ValueError, match="unknown field"):
        g.score_files([], options={"pipelin": {}})
    with pytest.raises(ValueError, match="min_still_s"):
        g.score_log(g.read_log(str(next(folder.rglob("city-1.csv")))), options={"pipeline": {"min_still_s": -1}})


def test_a_folder_of_raw_exports_gets_one_import_hint_per_recording(samples, tmp_path, capsys):
    wild = samples / "wild"
    failed = [str(wild / "sensor-logger" / "Accelerometer.csv"), str(wild / "sensor-logger" / "Gyroscope.csv"), str(wild / "ros" / "imu.csv")]
    hints = g.folder_hints(failed)
    assert len(hints) == 2 and "(import preset sensor-logger)" in hints[0] and "(import preset ros)" in hints[1]
    assert hints[0].startswith(str(wild / "sensor-logger") + ": it looks like a recording of") and "gyrodrift.import_files([" in hints[0]
    # The fleet job: the files are error rows, the hint is printed once for the recording.
    shutil.copytree(wild / "sensorlog", tmp_path / "phone")
    assert fleet.main([str(tmp_path), "--workers", "1"]) == 0
    err = capsys.readouterr().err
    assert err.count("it looks like a recording of") == 1 and "(import preset sensorlog)" in err
    # Files that are not v1 logs (kind "foreign"): the way that reads them, once, by how the
    # job read them.
    assert err.count("1 file is not a v1 log (no time_s column): --import reads the exports") == 1, err
    (tmp_path / "mine.csv").write_text("PacketCounter,SampleTimeFine,Gyr_Z\n1,1000,0.5\n2,2000,0.5\n")
    assert fleet.main([str(tmp_path), "--workers", "1", "--import"]) == 0
    err = capsys.readouterr().err
    assert err.count("1 file is not a v1 log (no time_s column) and no logger preset reads it: --recipe R") == 1, err


def test_the_fleet_job_with_import_scores_a_zipped_export_as_a_drive(samples, tmp_path):
    """A logger's zipped export in the folder: with --import a drive of its own, as its files
    imported give; without, not looked at."""
    import zipfile

    sl = samples / "wild" / "sensor-logger"
    with zipfile.ZipFile(tmp_path / "drive.zip", "w", zipfile.ZIP_DEFLATED) as z:
        for f in sorted(sl.iterdir()):
            z.write(f, "Drive/" + f.name)
    shutil.copy(samples / "train" / "city-1.csv", tmp_path / "city-1.csv")
    assert fleet.find_inputs(str(tmp_path)) == {"csv": [str(tmp_path / "city-1.csv")]}
    assert fleet.find_inputs(str(tmp_path), zips=True) == {"csv": [str(tmp_path / "city-1.csv"), str(tmp_path / "drive.zip")]}
    rows = g.score_files([str(tmp_path / "drive.zip")], 1, import_raw=True)
    assert len(rows) == 1 and rows[0]["error"] is None and rows[0]["name"] == "drive"
    log, _, _ = g.import_files([str(sl / f) for f in ("Gyroscope.csv", "Gravity.csv", "Location.csv")])
    assert rows[0]["e_psi_hdr_deg"] == g.hdr(log)["E_psi_hdr_deg"]


def test_score_files_imports_raw_exports_as_the_cli_does(cli, samples, tmp_path):
    wild = samples / "wild"
    paths = sorted(str(p) for p in wild.rglob("*.csv"))
    assert all(r["error"] for r in g.score_files(paths, 1))
    rows = g.score_files(paths, 2, import_raw=True)
    assert sorted(r["name"] for r in rows) == ["SensorLog.csv (SensorLog)", "phyphox", "px4", "ros", "sensor-logger"]
    assert not any(r["error"] for r in rows)
    out = tmp_path / "rows.json"
    cli("report", "--dir", str(wild), "--import", "--out", str(out))
    want = {r["file"]: r for r in json.loads(out.read_text())}
    for r in rows:
        assert r["ne_psi_pipeline_deg_per_min"] == want[r["file"]]["ne_psi_pipeline_deg_per_min"], r["file"]


def test_the_dask_job_imports_raw_exports_with_import(samples, tmp_path, capsys):
    shutil.copytree(samples / "wild", tmp_path / "wild")
    assert fleet.main([str(tmp_path / "wild"), "--workers", "2", "--import"]) == 0
    captured = capsys.readouterr()
    assert "it looks like a recording of" not in captured.err and "5 drives" not in captured.err
    assert "| pipeline | 5 |" in captured.out, captured.out
    # A folder's files stay in one task, however small the chunks.
    groups = fleet.chunks(sorted(str(p) for p in (tmp_path / "wild").rglob("*.csv")), 1, keep_folders=True)
    assert len(groups) == 5 and all(len({os.path.dirname(p) for p in g}) == 1 for g in groups)


def _as_my_logger(v1_path):
    """A v1 log as a logger of our own writes it: ms, deg/s, a clockwise course, km/h, ';'."""
    out = ["stamp_ms;gyro_z_dps;course;speed_kmh"]
    for line in v1_path.read_text().splitlines():
        if line.startswith("#") or line.startswith("time_s"):
            continue
        f = line.split(",")
        course = "" if f[3] == "" else repr(-float(f[3]))
        out.append(f"{float(f[0]) * 1000};{f[1]};{course};{float(f[4]) * 3.6}")
    return "\n".join(out) + "\n"


MY_RECIPE = {
    "bias_s": 20,
    "table": [{"id": "log", "file": "drive.txt", "delimiter": ";", "time": {"column": "stamp_ms", "unit": "ms"}}],
    "yaw_rate": {"table": "log", "column": "gyro_z_dps", "unit": "deg/s", "positive": "ccw"},
    "heading": {"source": "column", "table": "log", "column": "course", "unit": "deg", "positive": "cw"},
    "speed": {"source": "column", "table": "log", "column": "speed_kmh", "unit": "km/h"},
}


def test_a_fleet_of_ones_own_logger_is_scored_by_a_recipe_as_the_cli_does(cli, samples, tmp_path):
    d = tmp_path / "mine"
    (d / "week2").mkdir(parents=True)
    (d / "monday.txt").write_text(_as_my_logger(samples / "train" / "city-1.csv"))
    (d / "week2" / "tuesday.txt").write_text(_as_my_logger(samples / "test" / "highway-3.csv"))
    recipe = tmp_path / "mine.json"
    recipe.write_text(json.dumps(MY_RECIPE))
    assert g.recipe_endings(str(recipe)) == [".txt"] and g.recipe_endings(MY_RECIPE) == [".txt"]
    paths = sorted(str(p) for p in d.rglob("*.txt"))
    rows = g.score_files(paths, 2, recipe=MY_RECIPE)
    assert sorted(r["name"] for r in rows) == ["monday", "tuesday"] and not any(r["error"] for r in rows)
    out = tmp_path / "rows.json"
    cli("report", "--dir", str(d), "--recipe", str(recipe), "--out", str(out))
    want = {r["file"]: r for r in json.loads(out.read_text())}
    for r in rows:
        assert r["ne_psi_pipeline_deg_per_min"] == want[r["file"]]["ne_psi_pipeline_deg_per_min"], r["file"]
    # The Dask job: --recipe finds the .txt files and gives the same rows.
    frame = fleet.run(str(d), workers=2, progress=False, recipe=str(recipe))
    assert sorted(frame["name"]) == ["monday", "tuesday"] and frame["error"].isna().all()
    assert fleet.main([str(d), "--workers", "2", "--recipe", str(recipe), "--import"]) == 2


def test_gzipped_logs_read_and_score_as_the_plain_files(samples, tmp_path):
    """A gzip-compressed log (drive.csv.gz, as fleets store them): read_log, score_files and
    the fleet job's folder listing take it as the plain file, named without .csv.gz."""
    import gzip

    plain = samples / "train" / "city-1.csv"
    text = "".join(l for l in plain.read_text().splitlines(keepends=True) if not l.startswith("# name:"))
    (tmp_path / "day1").mkdir()
    (tmp_path / "day1" / "city-1.csv.gz").write_bytes(gzip.compress(text.encode()))
    (tmp_path / "city-1.csv").write_text(text)
    assert fleet.find_inputs(str(tmp_path)) == {"csv": [str(tmp_path / "city-1.csv"), str(tmp_path / "day1" / "city-1.csv.gz")]}
    gz = g.read_log(str(tmp_path / "day1" / "city-1.csv.gz"))
    assert np.array_equal(gz.column("gyro_dps"), g.read_log(str(plain)).column("gyro_dps"))
    a, b = g.score_files([str(tmp_path / "city-1.csv"), str(tmp_path / "day1" / "city-1.csv.gz")], 1)
    assert b["name"] == "city-1" and b["error"] is None
    assert a["e_psi_pipeline_deg"] == b["e_psi_pipeline_deg"]


def test_a_log_saved_with_semicolons_and_decimal_commas_reads_as_the_comma_log(samples, tmp_path):
    """A v1 log as a spreadsheet saves it where the decimal mark is a comma (`;` between
    cells, CRLF, a byte-order mark): read_log, Log.parse and Log.from_bytes read the comma
    log's columns and metadata; a bad cell is named by the file's line and column."""
    plain = samples / "train" / "city-1.csv"
    text = plain.read_text()
    saved = "\ufeff" + "\r\n".join(l if l.startswith("#") else l.replace(",", ";").replace(".", ",") for l in text.splitlines())
    (tmp_path / "eu.csv").write_bytes(saved.encode())
    want = g.read_log(str(plain))
    for got in [g.read_log(str(tmp_path / "eu.csv")), g.Log.parse(saved), g.Log.from_bytes(saved.encode())]:
        for c in ["time_s", "gyro_dps", "temp_c", "ref_heading_deg", "speed_mps"]:
            assert np.array_equal(got.column(c), want.column(c), equal_nan=True), c
        assert got.meta() == want.meta()
    with pytest.raises(ValueError, match=r'line 3, column gyro_dps: "1.5x" is not a number'):
        g.Log.parse("time_s;gyro_dps\r\n0;1,5\r\n0,1;1,5x\r\n")


def test_a_last_line_cut_short_is_dropped_with_a_warning(samples, tmp_path):
    """A logger stopped mid-line: read_log, Log.parse and the fleet's rows drop the last
    line cut short and say so (a UserWarning; the row's warnings)."""
    text = (samples / "train" / "city-1.csv").read_text()
    cut_at = text.rstrip().rfind("\n")
    (tmp_path / "cut.csv").write_text(text[: cut_at + 6])
    want = g.Log.parse(text[: cut_at + 1])
    said = "its last line, cut short (2 of 5 cells, no line end), dropped"
    for read in [lambda: g.read_log(str(tmp_path / "cut.csv")), lambda: g.Log.parse(text[: cut_at + 6])]:
        with pytest.warns(UserWarning, match=re.escape(said)):
            got = read()
        assert len(got) == len(want) and np.array_equal(got.column("gyro_dps"), want.column("gyro_dps"))
    (row,) = g.score_files([str(tmp_path / "cut.csv")], 1)
    assert row["error"] is None and said in row["warnings"]


def test_two_logs_joined_are_refused_naming_the_seconds_first_line(samples, tmp_path):
    """Two logs in one file (`cat a.csv b.csv`): read_log, Log.parse and the fleet's row name
    the second log's first line, not a short row; Log.read_joined reads each."""
    a = (samples / "train" / "city-1.csv").read_text()
    b = (samples / "train" / "city-2.csv").read_text()
    (tmp_path / "joined.csv").write_text(a + b)
    line = len(a.splitlines()) + 1
    said = f"line {line}: a '#' line after the rows (\"# name: City 2\"): a second log joined on?"
    for read in [lambda: g.read_log(str(tmp_path / "joined.csv")), lambda: g.Log.parse(a + b)]:
        with pytest.raises(ValueError, match=re.escape(said)):
            read()
    (row,) = g.score_files([str(tmp_path / "joined.csv")], 1)
    assert said in row["error"]
    with pytest.raises(ValueError, match=re.escape("gyrodrift.Log.read_joined reads each log in it")) as e:
        g.Log.read(str(tmp_path / "joined.csv"))
    assert e.value.code == "joined"
    # Log.read_joined: each log as read alone; a '#' note after the last rows said, not a log.
    (tmp_path / "noted.csv").write_text(a + b + "# stopped by the user\n")
    with pytest.warns(UserWarning, match=re.escape(f"(from line {line}): the '#' lines from line")):
        logs = g.Log.read_joined(str(tmp_path / "noted.csv"))
    alone = [g.Log.parse(a), g.Log.parse(b)]
    assert [x.meta()["name"] for x in logs] == ["City 1", "City 2"]
    for got, want in zip(logs, alone):
        assert len(got) == len(want) and np.array_equal(got.column("gyro_dps"), want.column("gyro_dps"))
    # The fleet with {"input": {"joined": "split"}}: a row each, saying which log it is.
    rows = g.score_files([str(tmp_path / "joined.csv")], 1, {"input": {"joined": "split"}})
    assert [r["name"] for r in rows] == ["City 1", "City 2"] and all(r["error"] is None for r in rows)
    assert rows[1]["warnings"].startswith(f"log 2 of 2 joined in the file, from line {line}")


def test_a_clock_reset_is_refused_and_read_in_parts(samples, tmp_path):
    """A logger restarting its clock without a new header: refused naming the line as a clock
    reset, with read_joined as the way on (not time_order="fix"); read_joined and the fleet's
    joined split read each part as the log it is."""
    a = (samples / "train" / "city-1.csv").read_text()
    b = (samples / "train" / "city-2.csv").read_text()
    rows = [l for l in b.splitlines() if l and not l.startswith("#") and not l.startswith("time_s")]
    (tmp_path / "reset.csv").write_text(a + "\n".join(rows) + "\n")
    line = len(a.splitlines()) + 1
    for order in ["error", "fix"]:
        with pytest.raises(ValueError, match=re.escape(f"line {line}, column time_s: time 0 goes back")) as e:
            g.Log.read(str(tmp_path / "reset.csv"), time_order=order)
        assert "a clock reset?" in str(e.value) and "read_joined reads each part" in str(e.value)
        assert 'time_order="fix" merges' not in str(e.value)
        assert e.value.code == "clock_reset"
    with pytest.warns(UserWarning, match=re.escape(f"(from line {line}): its clock reset on this line (time 0 after 1164)")):
        logs = g.Log.read_joined(str(tmp_path / "reset.csv"))
    assert [x.meta()["name"] for x in logs] == ["City 1 (1)", "City 1 (2)"]
    assert np.array_equal(logs[1].column("gyro_dps"), g.Log.parse(b).column("gyro_dps"))
    rows = g.score_files([str(tmp_path / "reset.csv")], 1, {"input": {"joined": "split"}})
    assert [r["name"] for r in rows] == ["City 1 (1)", "City 1 (2)"] and all(r["error"] is None for r in rows)
    assert f"from line {line}; its clock reset on this line" in rows[1]["warnings"]


def test_a_refusal_another_reading_mends_carries_its_kind_as_code(tmp_path):
    """Each parser refusal says by `code` which reading mends it (core's Refusal), so a fleet
    job sorts its failures without matching the words; any other parse error's code is None."""
    rows = "time_s,gyro_dps,temp_c\n0,1,20\n1,1,20\n"
    for text, code in [
        (rows + "1,1,20\n", "time_order"),
        (rows + "5,1,20\n0,1,20\n", "clock_reset"),
        (rows + "# name: b\ntime_s,gyro_dps\n0,1\n", "joined"),
        (rows + "2,1\n3,1,20\n", "cut_row"),
        ("Time (s);Gyroscope z (rad/s)\n0;1\n1;1\n", "foreign"),
        (rows + "2,x,20\n", None),
    ]:
        (tmp_path / "a.csv").write_text(text)
        for read in [lambda: g.Log.parse(text), lambda: g.Log.from_bytes(text.encode()), lambda: g.Log.read(str(tmp_path / "a.csv"))]:
            with pytest.raises(ValueError, match=r"line \d+") as e:
                read()
            assert e.value.code == code, (text, str(e.value))
    with pytest.raises(ValueError) as e:
        g.Log.read_joined(str(tmp_path / "a.csv"))
    assert e.value.code is None and "is not a number" in str(e.value)


def test_a_log_in_windows_1252_reads_with_a_warning(samples, tmp_path):
    """Excel's "CSV" on Windows is Windows-1252: read_log reads a name with a "ü" and says so."""
    text = (samples / "train" / "city-1.csv").read_text().replace("# name: City 1", "# name: Fahrt München")
    (tmp_path / "latin.csv").write_bytes(text.encode("cp1252"))
    with pytest.warns(UserWarning, match=re.escape("its text read as Windows-1252 (it is not UTF-8)")):
        got = g.read_log(str(tmp_path / "latin.csv"))
    assert got.meta()["name"] == "Fahrt München"
    assert np.array_equal(got.column("gyro_dps"), g.read_log(str(samples / "train" / "city-1.csv")).column("gyro_dps"))


def test_a_loggers_table_refused_for_its_time_names_the_draft(tmp_path):
    """read_log of a table the import's draft reads (time in ms, date-times in time_s)
    names draft_recipe; a v1 log with one bad time further down does not."""
    ms = tmp_path / "ms.csv"
    ms.write_text("time_ms,gyro_dps\n0,0.1\n100,0.2\n")
    iso = tmp_path / "iso.csv"
    iso.write_text("time_s,gyro_dps\n2026-11-28T10:00:00.000Z,0.1\n2026-11-28T10:00:00.100Z,0.1\n")
    bad = tmp_path / "bad.csv"
    bad.write_text("time_s,gyro_dps\n0,1\nx,2\n")
    for p in [ms, iso]:
        with pytest.raises(ValueError, match=r"gyrodrift\.draft_recipe\(\[.*\]\) drafts a recipe"):
            g.read_log(str(p))
        assert g.draft_recipe([str(p)])["recipe"]["yaw_rate"]["column"] == "gyro_dps"
    with pytest.raises(ValueError) as e:
        g.read_log(str(bad))
    assert "line 3, column time_s" in str(e.value) and "draft_recipe" not in str(e.value)


def test_dask_on_an_object_store_url_scores_as_the_local_folder(folder, samples, tmp_path):
    """INPUT as an fsspec URL (s3://... in use; memory:// here, in this process, which the
    LocalCluster's worker threads share): CSV logs, gzipped ones, a broken one and a missing
    object score as the same files on disk do, labelled by their URLs; a Parquet dataset
    partitioned by drive too; --import refuses a URL."""
    import gzip

    import fsspec

    mem = fsspec.filesystem("memory")
    root = f"/gd-fleet-{os.getpid()}"
    local = sorted(folder.rglob("*.csv"))
    for p in local:
        rel = p.relative_to(folder).as_posix()
        data = p.read_bytes()
        if rel.startswith("sim/sim-00"):
            mem.pipe(f"{root}/csv/{rel}.gz", gzip.compress(data))
        else:
            mem.pipe(f"{root}/csv/{rel}", data)
    rows = fleet.run(f"memory://{root}/csv", workers=2, chunk_bytes=1_500_000)
    assert len(rows) == 20 and rows["file"].str.startswith("memory://").all()
    want = g.rows_to_pandas(g.score_files([str(p) for p in local]))
    # Labelled by URL instead of path (and a failed file's row named so): the same after the folder.
    rel = lambda c: c.str.replace(r"^.*/(csv|fleet\d*)/", "", regex=True).str.replace(".gz", "")  # noqa: E731
    strip = lambda df: df.assign(file=rel(df["file"]), name=rel(df["name"])).sort_values(["file", "part"]).reset_index(drop=True)  # noqa: E731
    got, exp = strip(rows), strip(want)
    pd.testing.assert_frame_equal(got.drop(columns=["error"]), exp.drop(columns=["error"]), check_dtype=False)
    assert (got["error"].notna() == exp["error"].notna()).all()
    assert fleet.score_urls([f"memory://{root}/csv/none.csv"])[0]["error"].startswith("cannot open")
    # A Parquet dataset partitioned by drive, on the same filesystem.
    log = g.read_log(str(samples / "train" / "city-1.csv"))
    df = g.to_pandas(log)
    with mem.open(f"{root}/pq/drive=city-1/part-0.parquet", "wb") as f:
        df.to_parquet(f, index=False)
    pq_rows = fleet.run(f"memory://{root}/pq", workers=1)
    assert list(pq_rows["file"]) == ["city-1"]
    assert pq_rows["ne_psi_pipeline_deg_per_min"][0] == pytest.approx(g.score_log(log, "city-1")[0]["ne_psi_pipeline_deg_per_min"], rel=1e-12)
    with pytest.raises(ValueError, match="--import and --recipe read local folders only"):
        fleet.find_inputs(f"memory://{root}/csv", zips=True)
    mem.rm(root, recursive=True)


def test_read_log_and_from_bytes_take_a_url_and_gzip(samples):
    """read_log on an fsspec URL (memory:// here) and Log.from_bytes: the log the file gives,
    gzipped or not; bad content a ValueError naming the URL, line and column; a missing
    object an OSError naming it."""
    import gzip

    import fsspec

    mem = fsspec.filesystem("memory")
    root = f"/gd-read-{os.getpid()}"
    text = (samples / "train" / "city-1.csv").read_bytes()
    mem.pipe(f"{root}/city-1.csv.gz", gzip.compress(text))
    mem.pipe(f"{root}/bad.csv", b"time_s,gyro_dps\n0,1\n1,x\n")
    local = g.read_log(str(samples / "train" / "city-1.csv"))
    for log in (g.read_log(f"memory://{root}/city-1.csv.gz"), g.Log.from_bytes(text), g.Log.from_bytes(gzip.compress(text))):
        assert log.name == local.name and np.array_equal(log.column("gyro_dps"), local.column("gyro_dps"))
    with pytest.raises(ValueError, match=rf"memory://{root}/bad.csv: line 3, column gyro_dps"):
        g.read_log(f"memory://{root}/bad.csv")
    with pytest.raises(OSError, match=rf"memory://{root}/none.csv: cannot open"):
        g.read_log(f"memory://{root}/none.csv")
    # Log.read is local: a URL given to it says where URLs are read.
    with pytest.raises(OSError, match=r"Log.read reads local files; gyrodrift.read_log fetches a URL"):
        g.Log.read(f"memory://{root}/city-1.csv.gz")
    with pytest.raises(ValueError, match="a damaged or cut gzip file"):
        g.Log.from_bytes(gzip.compress(text)[:300])
    mem.rm(root, recursive=True)


def test_a_log_out_of_time_order_is_refused_or_put_in_order(samples, tmp_path):
    """A v1 log whose time repeats: read_log refuses it naming the line and the argument that
    fixes it; time_order="fix" merges the repeat (a UserWarning says so) and scores as the
    log without it; the fleet's options take the same policy, its row warning saying so."""
    import warnings

    lines = (samples / "train" / "city-1.csv").read_text().splitlines()
    h = next(i for i, l in enumerate(lines) if l.startswith("time_s"))
    dup = tmp_path / "dup.csv"
    dup.write_text("\n".join(lines[: h + 400] + [lines[h + 399]] + lines[h + 400 :]) + "\n")
    with pytest.raises(ValueError, match=r"line \d+, column time_s: .*repeats.*; time_order=\"fix\" merges"):
        g.read_log(str(dup))
    with pytest.warns(UserWarning, match="time order: 1 rows of a repeated time merged"):
        log = g.read_log(str(dup), time_order="fix")
    plain = g.read_log(str(samples / "train" / "city-1.csv"))
    assert np.array_equal(log.column("gyro_dps"), plain.column("gyro_dps"))
    with pytest.raises(ValueError, match='time_order "sort"'):
        g.read_log(str(dup), time_order="sort")
    with pytest.warns(UserWarning, match="log: time order: 1 rows"):
        assert len(g.Log.from_bytes(dup.read_bytes(), time_order="fix")) == len(plain)
    # A log in order warns of nothing.
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        g.read_log(str(samples / "train" / "city-1.csv"), time_order="fix")
    rows = g.score_files([str(dup)], options={"input": {"time_order": "fix"}})
    assert rows[0]["warnings"].startswith("time order: 1 rows of a repeated time merged") and rows[0]["error"] is None
    assert g.score_files([str(dup)])[0]["error"].endswith("time must strictly increase")


def test_read_log_reads_one_drives_parquet_file_and_refuses_a_table_of_drives(samples, tmp_path):
    """A drive stored as Parquet (CSV v1's columns, as the fleet job reads a dataset with a
    drive per file): read_log reads it as the CSV, named by its file, by its name or by its
    first bytes; a table of several drives, or a bad column, is a ValueError naming the file."""
    csv = g.read_log(str(samples / "train" / "city-1.csv"))
    df = g.to_pandas(csv)
    df.to_parquet(tmp_path / "city-1.parquet", index=False)
    df.to_parquet(tmp_path / "no-suffix", index=False)
    for path in [tmp_path / "city-1.parquet", str(tmp_path / "no-suffix")]:
        log = g.read_log(path)
        for c in csv.column_names():
            assert np.array_equal(log.column(c), csv.column(c), equal_nan=True), c
    assert g.read_log(tmp_path / "city-1.parquet").name == "city-1"
    two = pd.concat([df.assign(drive="a"), df.assign(drive="b")])
    two.to_parquet(tmp_path / "fleet.parquet", index=False)
    with pytest.raises(ValueError, match=r"fleet\.parquet: a Parquet table of 2 drives \(column 'drive'\): score them with python -m gyrodrift\.fleet"):
        g.read_log(tmp_path / "fleet.parquet")
    df.assign(time_s=df["time_s"][::-1].to_numpy()).to_parquet(tmp_path / "backward.parquet", index=False)
    with pytest.raises(ValueError, match=r"^.*backward\.parquet: "):
        g.read_log(tmp_path / "backward.parquet")
    # A CSV is still read by core, whatever its name says.
    assert len(g.read_log(samples / "train" / "city-1.csv")) == len(csv)
