"""The Python package against the CLI: the same reports, the same errors, the same shards merged.

Run from the repository root (``tests/python/run`` does): the scenes are read by their paths in
``specs/`` and ``tests/specs/``, and ``reports/`` holds what ``gearloss run`` wrote for each
``specs/`` scene (a Rust test keeps them current).
"""

import json
import os
import pathlib
import threading
import time

import pandas
import pandas.testing
import pytest

import gearloss
import gearloss.dask

ROOT = pathlib.Path(__file__).resolve().parents[2]
SPECS = sorted((ROOT / "specs").glob("*.gear"))
ERR_SNAPSHOTS = ROOT / "tests/it/snapshots"


@pytest.fixture(autouse=True)
def at_root(monkeypatch):
    monkeypatch.chdir(ROOT)


def scene(path):
    return gearloss.Scene.from_file(pathlib.Path(path).relative_to(ROOT).as_posix())


@pytest.mark.parametrize("path", SPECS, ids=lambda p: p.name)
def test_every_spec_gives_the_cli_report(path):
    """`run(...).data` is the CLI's report.json and `.records` its records.csv (a drive's
    drive_records.csv), for every scene."""
    report = gearloss.run(scene(path))
    folder = ROOT / "reports" / report.name
    assert json.loads((folder / "report.json").read_text()) == report.data
    if (folder / "records.csv").exists():
        pandas.testing.assert_frame_equal(report.records, pandas.read_csv(folder / "records.csv"))
    elif (folder / "drive_records.csv").exists():
        # A drive's records are its drive_records.csv.
        pandas.testing.assert_frame_equal(report.records, pandas.read_csv(folder / "drive_records.csv"))
    else:
        # A report at several oil temperatures has its records in each run: asking says so.
        with pytest.raises(LookupError):
            report.records
    assert report.markdown() == (folder / "report.md").read_text()
    for name in report.files:
        if name.endswith(".svg") and not name.startswith("timing_") and "/" not in name:
            assert report.svg(name) == (folder / name).read_text(), name


def err_fixtures():
    for snap in sorted(ERR_SNAPSHOTS.glob("it__specs__err_fixtures_fail_with_diagnostics@*.snap")):
        name = snap.name.split("@", 1)[1][: -len(".snap")]
        yield pytest.param(name, snap, id=name)


@pytest.mark.parametrize("name,snap", list(err_fixtures()))
def test_a_bad_scene_raises_the_cli_diagnostics(name, snap):
    """Every error fixture raises SceneError whose str() is the CLI's rendering (the insta snapshot)
    and whose diagnostics carry the file, line and column the rendering shows."""
    path = f"tests/specs/err/{name}"
    try:
        text = (ROOT / path).read_bytes().decode("utf-8")
    except UnicodeDecodeError:
        pytest.skip("not UTF-8: the CLI refuses it before parsing")
    with pytest.raises(gearloss.SceneError) as caught:
        gearloss.Scene(text, name=path)
    expected = snap.read_bytes().decode("utf-8").split("---\n", 2)[2]
    assert str(caught.value).strip() == expected.strip()
    first = caught.value.diagnostics[0]
    assert expected.startswith(f"{first['file']}:{first['line']}:{first['column']}: {first['message']}")
    assert all(d["help"] for d in caught.value.diagnostics)


def test_replace_equals_the_text_edited_by_hand():
    base = scene(ROOT / "specs/fzg_type_c.gear")
    replaced = base.replace(pinion_speed="500..1500 rpm count 3", oil_temperature="60 degC")
    by_hand = base.text.replace("pinion_speed  = [100, 1000, 3000] rpm", "pinion_speed  = 500..1500 rpm count 3")
    assert by_hand != base.text
    by_hand = by_hand.replace("pinion_speed  = 500..1500 rpm count 3", "pinion_speed  = 500..1500 rpm count 3")
    a = gearloss.run(replaced).pair.efficiency
    b = gearloss.run(gearloss.Scene(by_hand, name=base.name)).pair.efficiency
    pandas.testing.assert_frame_equal(a, b)
    assert sorted(a["pinion_speed_rad_s"].round(4).unique()) == [52.3599, 104.7198, 157.0796]


def test_replace_is_checked_like_the_text():
    with pytest.raises(gearloss.SceneError) as caught:
        scene(ROOT / "specs/fzg_type_c.gear").replace(pinion_torque="300 rpm")
    assert any(d["kind"] == "WrongDimension" for d in caught.value.diagnostics)


def test_dask_shards_merge_into_the_single_run():
    """Shards as Dask tasks, merged as `gearloss merge` merges: the same report and records."""
    s = scene(ROOT / "specs/composite_speed_sweep.gear")
    whole = gearloss.run(s)
    for shards in (1, 4):
        merged = gearloss.dask.run(s, shards=shards)
        assert merged.data == whole.data
        pandas.testing.assert_frame_equal(merged.records, whole.records)


def test_a_shard_is_the_cli_shard():
    s = scene(ROOT / "specs/composite_speed_sweep.gear")
    part = gearloss.run(s, shard="2/3")
    assert "shard.json" in part.files or any(f.endswith(".json") for f in part.files)
    assert 0 < len(part.records) < len(gearloss.run(s).records)


def test_write_gives_the_cli_folder(tmp_path):
    report = gearloss.run(scene(ROOT / "specs/fzg_type_c.gear"))
    out = report.write(tmp_path)
    assert out == tmp_path / "fzg_type_c"
    for name in ("report.md", "report.json", "drive_records.csv", "stages/pair/records.csv", "stages/pair/contact_state.svg"):
        assert (out / name).read_bytes() == (ROOT / "reports/fzg_type_c" / name).read_bytes(), name
    assert gearloss.Report.from_folder(out).data == report.data
    report.write(tmp_path)  # again, in place of the first
    assert sorted(p.name for p in tmp_path.iterdir()) == ["fzg_type_c"]


def test_tidy_tables():
    # A scene of one pair runs as its one-stage drive: the budget is the drive's, a row per record row.
    gearbox = gearloss.run(scene(ROOT / "specs/fzg_c14_gearbox.gear"))
    budget = gearbox.budget
    assert {"total_loss_W", "bearings_load_W", "seals_W", "label", "formulation"} <= set(budget.columns)
    # Every law and formulation (issue 46: it used to keep the first of each point only).
    assert len(budget) == len(gearbox.efficiency) == 9 * 2 * 2
    keyed = budget.set_index(["torque_index", "speed_index", "label", "formulation"])
    assert keyed.index.is_unique
    assert budget["label"].nunique() == 2 and budget["formulation"].nunique() == 2
    for _, row in budget.iterrows():
        parts = row["gear_no_load_W"] + row["bearings_no_load_W"] + row["bearings_load_W"] + row["seals_W"]
        assert abs(row["power_loss_W"] + parts - row["total_loss_W"]) <= 1e-9 * row["total_loss_W"]
    dynamics = gearloss.run(scene(ROOT / "specs/fzg_dynamics.gear")).dynamics
    assert {"spectral_radius", "pinion_speed_rad_s"} <= set(dynamics.columns) and len(dynamics) > 0
    assert gearloss.run(scene(ROOT / "specs/fzg_type_c.gear")).pair.budget.empty


def test_oil_temperature_runs():
    report = gearloss.run(scene(ROOT / "specs/fzg_c14_oil_temperatures.gear"))
    runs = report.runs
    assert len(runs) == 5 and all(not r.efficiency.empty for r in runs.values())


def test_run_errors_map_to_run_error(tmp_path):
    """Errors after lowering: gearloss.RunError with the failure's kind and hints (src/python/error.rs)."""
    (tmp_path / "not_a_shard").mkdir()
    with pytest.raises(gearloss.RunError) as caught:
        gearloss.merge([tmp_path / "not_a_shard"])
    assert caught.value.kind == "not_a_shard"
    assert caught.value.hints and "--shard" in caught.value.hints[0]


def test_runs_release_the_gil():
    """While runs compute in two threads, Python keeps running in the main thread (a run holds no
    GIL): it wakes from 1 ms sleeps dozens of times during them (a run that held the GIL would
    keep it from waking until it returned). The two runs overlap in time and each gives the
    single-threaded report."""
    s = scene(ROOT / "specs/composite_speed_sweep.gear").replace(pinion_speed="100..3000 rpm count 400")
    expected = gearloss.run(s).data
    spans, results = [], []

    def one():
        t0 = time.perf_counter()
        results.append(gearloss.run(s).data)
        spans.append((t0, time.perf_counter()))

    threads = [threading.Thread(target=one) for _ in range(2)]
    for t in threads:
        t.start()
    turns = 0
    while any(t.is_alive() for t in threads):
        time.sleep(0.001)
        turns += 1
    for t in threads:
        t.join()
    assert results == [expected, expected]
    (a0, a1), (b0, b1) = spans
    assert max(a0, b0) < min(a1, b1), f"the runs did not overlap: {spans}"
    assert turns > 20, f"the main thread woke {turns} times during runs of {a1 - a0:.3f} s and {b1 - b0:.3f} s"


def test_dask_on_a_local_cluster_of_two_worker_processes():
    """Four shards on a distributed LocalCluster of 2 worker processes: the single run's report."""
    distributed = pytest.importorskip("distributed")
    s = scene(ROOT / "specs/composite_speed_sweep.gear")
    whole = gearloss.run(s)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        with distributed.Client(cluster) as client:
            merged = gearloss.dask.run(s, shards=4, client=client)
    assert merged.data == whole.data
    pandas.testing.assert_frame_equal(merged.records, whole.records)


def readme_python_blocks():
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    blocks = text.split("```python\n")[1:]
    return [b.split("```", 1)[0] for b in blocks]


@pytest.mark.parametrize("block", readme_python_blocks(), ids=lambda b: b.splitlines()[0][:40])
def test_readme_python_examples_run(block):
    """Every ```python block of README runs as written, from the repository root."""
    assert readme_python_blocks(), "README has Python examples"
    exec(compile(block, "README.md", "exec"), {})


# Issue 40: the hostile calls of a held-out catalogue, each answered as the CLI would.


def test_from_file_refuses_what_is_not_a_regular_file(tmp_path):
    """/dev/zero and a FIFO are refused before anything is read (no memory run out, no block)."""
    import os

    fifo = tmp_path / "pipe.gear"
    os.mkfifo(fifo)
    for path in ("/dev/zero", fifo, tmp_path):
        started = time.monotonic()
        with pytest.raises(OSError, match="not a regular file"):
            gearloss.Scene.from_file(path)
        assert time.monotonic() - started < 1.0
    big = tmp_path / "big.gear"
    big.write_bytes(b"#" * (16 * 2**20 + 1))
    with pytest.raises(OSError, match="larger than the limit"):
        gearloss.Scene.from_file(big)


def test_dask_shards_are_capped_at_the_point_count():
    """10⁷ shards of a 6-point scene are 6 tasks: the same report as one run."""
    s = scene(ROOT / "specs/fzg_type_c.gear")
    assert gearloss.dask.run(s, shards=10**7).data == gearloss.run(s).data
    with pytest.raises(ValueError, match="at least 1"):
        gearloss.dask.run(s, shards=0)


def _interrupted_within(work, seconds):
    """Ctrl-C simulated 0.5 s into `work` raises KeyboardInterrupt within `seconds`. Python's own
    SIGINT handler is put in place for the test (an earlier test's cluster may leave its own)."""
    import _thread
    import signal

    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    timer = threading.Timer(0.5, _thread.interrupt_main)
    started = time.monotonic()
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            work()
        assert time.monotonic() - started < seconds
    finally:
        timer.cancel()
        signal.signal(signal.SIGINT, previous)


def test_ctrl_c_stops_a_long_run_within_a_second():
    """Ctrl-C (SIGINT, here simulated 0.5 s in) during a 90 000-point run raises KeyboardInterrupt
    within about a second, not when the run (tens of seconds) ends."""
    s = scene(ROOT / "specs/fzg_type_c.gear").replace(
        pinion_torque="50..400 N*m count 300", pinion_speed="100..3000 rpm count 300"
    )
    _interrupted_within(lambda: gearloss.run(s), seconds=2.5)


def test_ctrl_c_stops_a_long_drive_run_within_a_second():
    """The same for a drive: a 160 000-point sweep of the EV reducer (tens of seconds) stops within
    about a second of Ctrl-C (between blocks of 4 096 rows), not when it ends."""
    s = scene(ROOT / "specs/ev_two_stage_reducer.gear").replace(
        output_torque="50..1000 N*m count 400", output_speed="100..1500 rpm count 400"
    )
    _interrupted_within(lambda: gearloss.run(s), seconds=2.5)


def test_replace_errors_name_the_edited_text():
    """An error in a replaced value is located in the edited text, and the file name says so."""
    s = scene(ROOT / "specs/fzg_type_c.gear")
    with pytest.raises(gearloss.SceneError) as e:
        s.replace(pinion_torque="300 kg")
    d = [d for d in e.value.diagnostics if d["kind"] == "WrongDimension"][0]
    assert d["file"] == "specs/fzg_type_c.gear (with pinion_torque replaced)"
    edited = s.text.replace("[239.3, 372.6] N*m", "300 kg")
    line = edited.splitlines()[d["line"] - 1]
    assert line[d["column"] - 1 :].startswith("kg"), (line, d)


def test_concurrent_writes_from_processes_all_succeed(tmp_path):
    """Two processes writing the same folder 100 times each: every write succeeds, one folder and
    nothing else is left (the CLI's writer)."""
    import concurrent.futures

    report = gearloss.run(scene(ROOT / "specs/fzg_type_c.gear"))
    with concurrent.futures.ProcessPoolExecutor(max_workers=2) as pool:
        failures = sum(pool.map(_write_many, [(report.name, report._files, str(tmp_path))] * 2))
    assert failures == 0
    assert [p.name for p in tmp_path.iterdir()] == ["fzg_type_c"]
    assert gearloss.Report.from_folder(tmp_path / "fzg_type_c").data == report.data


def _write_many(args):
    name, files, out = args
    report, failures = gearloss.Report(name, files.items()), 0
    for _ in range(100):
        try:
            report.write(out)
        except OSError:
            failures += 1
    return failures


def test_a_failing_dask_shard_is_named_and_nothing_writes_after(tmp_path, monkeypatch):
    """Shard 2 of 3 fails: the error names it, and the other shards have finished writing before
    the temporary folder is removed (the work folder is empty afterwards)."""
    real = gearloss._native.run_to

    def flaky(name, text, out, shard, records=None):
        if shard.startswith("2/"):
            raise gearloss.RunError("the disk is full")
        time.sleep(0.3)
        return real(name, text, out, shard, records)

    monkeypatch.setattr(gearloss.dask._native, "run_to", flaky)
    s = scene(ROOT / "specs/fzg_type_c.gear")
    with pytest.raises(gearloss.RunError, match="shard 2 of 3 failed: the disk is full") as e:
        gearloss.dask.run(s, shards=3, workdir=tmp_path)
    assert e.value.shard == 2
    time.sleep(0.5)
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("shard", ["7/6", (3, 2), (1, 0), "0/6", "1/1000001", (-1, 2), (1.5, 2), "x/2", 3])
def test_a_shard_that_does_not_exist_is_a_value_error(shard):
    """The CLI's validation of ``--shard K/N`` (1 ≤ K ≤ N ≤ 10⁶), never a panic."""
    s = scene(ROOT / "specs/fzg_type_c.gear")
    with pytest.raises(ValueError, match="K/N|K, N") as e:
        gearloss.run(s, shard=shard)
    assert not isinstance(e.value, gearloss.SceneError)


def test_svg_of_a_missing_plot_lists_the_plots():
    report = gearloss.run(scene(ROOT / "specs/fzg_type_c.gear")).pair
    with pytest.raises(KeyError, match="contact_state.svg") as e:
        report.svg("nope.svg")
    assert "no plot 'nope.svg'" in str(e.value)
    assert "contact_state.svg" in report.plots


@pytest.mark.parametrize(
    "value, said",
    [(float("nan"), "is NaN: not a number"), (float("inf"), "is infinite"), (-80.0, "is negative")],
)
def test_replace_with_a_bad_number_says_what_is_wrong(value, said):
    s = scene(ROOT / "specs/fzg_type_c.gear")
    with pytest.raises(gearloss.SceneError) as e:
        s.replace(pinion_torque=value)
    messages = [d["message"] for d in e.value.diagnostics]
    assert any(said in m for m in messages), messages
    assert not any(m.endswith("but the value has no unit") for m in messages), messages


def test_a_drive_with_an_elastic_shaft_as_tables():
    """The EV reducer with its lay shaft on three places: the bearings table has all seven places
    at each of the six rows, the lay shaft's three among them, and the places' losses add up to
    the records' bearing columns (1e-9)."""
    report = gearloss.run(scene(ROOT / "specs/ev_reducer_three_bearing_lay_shaft.gear"))
    bearings, records = report.bearings, report.drive_records
    assert len(bearings) == 7 * 6
    assert {p for p in bearings["place"] if p.startswith("lay_")} == {"lay_1", "lay_2", "lay_3"}
    for row, r in records.set_index("row").iterrows():
        places = bearings[bearings["row"] == row]
        got = places["no_load_W"].sum() + places["load_W"].sum()
        want = r["bearings_no_load_W"] + r["bearings_load_W"]
        assert abs(got - want) <= 1e-9 * abs(want)


def test_a_drive_as_tables():
    """A drive of several stages (the EV reducer): drive_records with a row per point, law and
    formulation, and the long tables per stage, shaft and bearing place, whose parts add up to the
    records' columns (1e-9); a pair's report has none of them."""
    report = gearloss.run(scene(ROOT / "specs/ev_two_stage_reducer.gear"))
    records = report.drive_records
    assert len(records) == 6
    assert set(records["flow"]) == {"drive", "coast"}
    stages, shafts, bearings = report.stages, report.shafts, report.bearings
    assert len(stages) == 2 * 6 and set(stages["stage"]) == {"first", "second"}
    assert len(shafts) == 3 * 6 and set(shafts["shaft"]) == {"motor", "lay", "output"}
    assert len(bearings) == 6 * 6
    coast = stages[stages["flow"] == "coast"]
    assert set(coast["driving"]) == {"wheel"}
    for row, r in records.set_index("row").iterrows():
        mesh = stages[stages["row"] == row]["mesh_loss_W"].sum()
        assert abs(mesh - r["meshes_W"]) <= 1e-9 * r["total_W"]
        b = bearings[bearings["row"] == row]
        assert abs(b["no_load_W"].sum() + b["load_W"].sum() - r["bearings_no_load_W"] - r["bearings_load_W"]) <= 1e-9 * r["total_W"]
        s = shafts[shafts["row"] == row]
        assert abs(s["seals_W"].sum() - r["seals_W"]) <= 1e-9 * r["total_W"]
    pair = gearloss.run(scene(ROOT / "specs/fzg_type_c.gear")).pair
    for table in ("drive_records", "stages", "bearings"):
        with pytest.raises(LookupError, match="one gear pair"):
            getattr(pair, table)


def test_a_planetary_stage_as_a_table():
    """The planetary reducer: `report.planetary` has a row per record row; the members' torques
    balance, their powers add up to both meshes' loss, and the stage's η is Krüger's from η₀
    ((1 + 3η₀)/4 in drive, 4η₀/(η₀ + 3) in coast), to 1e-9; a drive without planets has none."""
    report = gearloss.run(scene(ROOT / "specs/planetary_reducer.gear"))
    p = report.planetary
    records = report.drive_records
    assert len(p) == len(records) == 12 and set(p["stage"]) == {"planetary"}
    rpm = 3.141592653589793 / 30.0
    for _, r in p.iterrows():
        torques = [r["sun_torque_N_m"], r["ring_torque_N_m"], r["carrier_torque_N_m"]]
        assert abs(sum(torques)) <= 1e-9 * abs(r["carrier_torque_N_m"])
        power = sum(t * r[f"{m}_speed_rpm"] * rpm for t, m in zip(torques, ["sun", "ring", "carrier"]))
        meshes = r["sun_planet_loss_W"] + r["planet_ring_loss_W"]
        assert abs(power - meshes) <= 1e-9 * abs(r["rolling_power_W"])
        eta0 = r["basic_efficiency"]
        assert abs(eta0 - r["sun_planet_efficiency"] * r["planet_ring_efficiency"]) <= 1e-12
    stages = report.stages.set_index("row")
    for row, r in p.set_index("row").iterrows():
        eta0 = r["basic_efficiency"]
        kruger = (1 + 3 * eta0) / 4 if stages.loc[row, "driving"] == "sun" else 4 * eta0 / (eta0 + 3)
        assert abs(stages.loc[row, "mesh_efficiency"] - kruger) <= 1e-9
    assert gearloss.run(scene(ROOT / "specs/ev_two_stage_reducer.gear")).planetary.empty


def test_a_drive_cycle_as_a_table():
    """A vehicle over WLTC 3b: `report.cycle` has a row per interval (1800), its losses add up to
    the report's totals (ten digits), and on every row the motor's energy is the box's output
    (the wheel's plus what the brakes take) and the loss; a pair's report has no cycle."""
    report = gearloss.run(scene(ROOT / "specs/ev_reducer_wltc.gear"))
    cycle = report.cycle
    assert len(cycle) == 1800
    assert {"t_start_s", "v_end_km_h", "wheel_torque_start_N_m", "motor_speed_end_rpm", "loss_J", "seals_J",
            "oil_temperature_end_C"} <= set(cycle.columns)
    whole = report.data["cycle"]["whole"]
    total = (whole["loss_drive_wh"] + whole["loss_recuperation_wh"]) * 3600.0
    assert abs(cycle["loss_J"].sum() - total) <= 1e-8 * total
    scale = cycle["motor_J"].abs() + cycle["wheel_J"].abs() + 1.0
    residual = cycle["motor_J"] - cycle["wheel_J"] - cycle["brakes_J"] - cycle["loss_J"]
    assert (residual.abs() <= 1e-8 * scale).all(), residual.abs().max()
    parts = cycle[["meshes_J", "gear_no_load_J", "bearings_no_load_J", "bearings_load_J", "seals_J"]].sum(axis=1)
    assert ((parts - cycle["loss_J"]).abs() <= 1e-8 * (cycle["loss_J"].abs() + 1.0)).all()
    with pytest.raises(LookupError, match="one gear pair"):
        gearloss.run(scene(ROOT / "specs/fzg_type_c.gear")).pair.cycle
    assert gearloss.run(scene(ROOT / "specs/planetary_reducer.gear")).cycle.empty  # a drive without a cycle


@pytest.mark.parametrize("name", ["FVA-Industriegetriebe_2stufig_1-4.rexs", "FVA-Industriegetriebe_2stufig_1-4.rexsj",
                                  "FVA-Industriegetriebe_2_stufig_1-6.rexs"])
def test_a_rexs_model_imports_and_runs(name):
    """`Scene.from_rexs` gives the CLI's scene (its text, its warnings), which runs: the drive's two
    stages with the file's teeth."""
    s = gearloss.Scene.from_rexs(ROOT / "tests/rexs" / name)
    assert "REXS cylindrical_stage" in s.text and any("tip_diameter" in w for w in s.warnings)
    report = gearloss.run(s)
    teeth = sorted(tuple(st["teeth"]) for st in report.data["stages"])
    assert teeth == [(23, 34), (27, 51)]


def test_a_broken_rexs_model_raises_rexs_error():
    """A broken model raises `RexsError` (a ValueError) naming the component, with a hint."""
    with pytest.raises(gearloss.RexsError) as e:
        gearloss.Scene.from_rexs(ROOT / "tests/rexs/err/unit_contradicts_the_attribute.rexs")
    assert isinstance(e.value, ValueError)
    assert "normal_module" in str(e.value) and "component 6" in e.value.component and e.value.hint
    with pytest.raises(gearloss.RexsError, match="none of its members is held by the casing") as e:
        gearloss.Scene.from_rexs(ROOT / "tests/rexs/planetary/FVA_Planetary_stage_-_Minus_gearing_1.1.rexsj")
    assert "planetary_stage" in e.value.component


def test_a_planetary_rexs_model_imports_and_runs():
    """FVA's planetary stage (zipped XML) imports into a planetary stage kind and runs."""
    s = gearloss.Scene.from_rexs(ROOT / "tests/rexs/planetary/FVA_Planetary_stage_-_Minus_gearing_1.1.rexsz")
    assert "planetary {" in s.text and "planets = 3" in s.text
    report = gearloss.run(s)
    assert "report.md" in report.files


@pytest.mark.parametrize("spec", ["fzg_type_c.gear", "helical_gearbox.gear", "fzg_c14_thermal.gear"])
def test_records_from_parquet_equal_the_csvs(spec):
    """`records=["parquet"]`: `Report.records` reads records.parquet, and its columns (the CSV's,
    then the parameters') hold the CSV's DataFrame's values exactly."""
    s = scene(ROOT / "specs" / spec)
    from_csv = gearloss.run(s).pair.records
    parquet = gearloss.run(s, records=["parquet"]).pair
    assert "records.parquet" in parquet.files and "records.csv" not in parquet.files
    from_parquet = parquet.records
    assert list(from_parquet.columns[: len(from_csv.columns)]) == list(from_csv.columns)
    assert all(c.startswith("param_") for c in from_parquet.columns[len(from_csv.columns):])
    pandas.testing.assert_frame_equal(from_parquet[from_csv.columns], from_csv, check_dtype=False, check_exact=True)


def test_drive_records_from_parquet_equal_the_csvs():
    """`records=["parquet"]` on a drive: `Report.drive_records` reads drive_records.parquet, the
    CSV's columns and values exactly, and the long tables follow from it."""
    s = scene(ROOT / "specs/planetary_two_stage.gear")
    from_csv = gearloss.run(s).drive_records
    parquet = gearloss.run(s, records=["parquet"])
    assert "drive_records.parquet" in parquet.files and "drive_records.csv" not in parquet.files
    pandas.testing.assert_frame_equal(parquet.drive_records, from_csv, check_dtype=False, check_exact=True)
    assert len(parquet.stages) == 2 * len(from_csv)


def test_drive_records_from_json_lines_equal_the_csvs():
    """`records=["jsonl"]` on a drive: drive_records.jsonl alone, and `Report.drive_records` reads
    it, the CSV's columns and values exactly."""
    s = scene(ROOT / "specs/planetary_two_stage.gear")
    from_csv = gearloss.run(s).drive_records
    jsonl = gearloss.run(s, records=["jsonl"])
    assert "drive_records.jsonl" in jsonl.files and "drive_records.csv" not in jsonl.files
    pandas.testing.assert_frame_equal(jsonl.drive_records, from_csv, check_dtype=False, check_exact=True)


@pytest.mark.parametrize("reader", ["polars", "duckdb"])
def test_polars_and_duckdb_read_records_parquet(reader, tmp_path):
    """README's one-liners for polars and DuckDB, where the package is installed (skipped otherwise):
    the same rows and mean efficiency as pandas reads."""
    module = pytest.importorskip(reader)
    run = gearloss.run(scene(ROOT / "specs/fzg_type_c.gear"), records=["parquet"])
    folder = run.write(tmp_path)
    path = folder / "records.parquet"
    expected = pandas.read_parquet(path)["mean_efficiency"].mean()
    if reader == "polars":
        df = module.read_parquet(path)
        assert df.height == len(run.records) and abs(df["mean_efficiency"].mean() - expected) < 1e-15
    else:
        ((mean,),) = module.sql(f"SELECT avg(mean_efficiency) FROM '{path}'").fetchall()
        assert abs(mean - expected) < 1e-12


def test_parquet_shards_on_dask_are_the_single_run():
    """Parquet records in Dask shards, merged: the single run's records.parquet rows."""
    s = scene(ROOT / "tests/specs/ok/large_sweep.gear")
    whole = gearloss.run(s, records="parquet")
    merged = gearloss.dask.run(s, shards=3, records=["parquet"])
    pandas.testing.assert_frame_equal(merged.records, whole.records, check_exact=True)


def test_a_drive_on_dask_is_the_single_run():
    """A drive of several stages in Dask shards, merged: the single run's report and drive records."""
    s = scene(ROOT / "specs/ev_two_stage_reducer.gear")
    whole = gearloss.run(s)
    merged = gearloss.dask.run(s, shards=3)
    assert merged.data == whole.data
    pandas.testing.assert_frame_equal(merged.drive_records, whole.drive_records)


def test_a_bare_negative_output_speed_of_a_drive_is_said_to_be_negative():
    """A drive's `output_speed = -80.0` (a bare number) gets the sign rule the text form gets, not
    only "no unit"."""
    s = scene(ROOT / "specs/ev_two_stage_reducer.gear")
    with pytest.raises(gearloss.SceneError) as e:
        s.replace(output_speed=-80.0)
    messages = [d["message"] for d in e.value.diagnostics]
    assert any("is negative" in m for m in messages), messages


def test_tables_of_the_other_kind_of_report_raise_lookup_error():
    """A pair's tables asked of a drive, and a drive's of a pair, say which tables the report has."""
    pair = gearloss.run(scene(ROOT / "specs/fzg_type_c.gear")).pair
    drive = gearloss.run(scene(ROOT / "specs/planetary_reducer.gear"))
    for table in ("drive_records", "stages", "stage_pairs", "shafts", "bearings", "planetary", "cycle"):
        with pytest.raises(LookupError, match="its tables are records"):
            getattr(pair, table)
    # Every table of a pair serves a drive too: its dynamics are its stage meshes' (none here).
    assert drive.dynamics.empty and drive.stage_pairs == {}
    assert len(drive.stages) > 0 and len(pair.efficiency) > 0
    # `records` serves every report: a drive's are its drive_records.
    pandas.testing.assert_frame_equal(drive.records, drive.drive_records)


def test_a_drives_efficiency_and_budget_are_the_pairs_tables():
    """`efficiency` and `budget` serve a drive as they serve a pair: a row per operating point, law
    and formulation, labelled by the law as the report labels it; the budget has a pair's columns
    for the whole box (its parts add up to `total_loss_W`, 1e-9, which in drive is P_in − P_out)
    beside each bearing place's, the efficiency each stage's η_mesh and the box's η."""
    drive = gearloss.run(scene(ROOT / "specs/ev_two_stage_reducer.gear"))
    pair = gearloss.run(scene(ROOT / "specs/fzg_c14_gearbox.gear"))
    budget, records = drive.budget, drive.drive_records
    assert len(budget) == len(records) > 0
    shared = {"label", "formulation", "power_loss_W", "gear_no_load_W", "bearings_no_load_W", "bearings_load_W",
              "seals_W", "total_loss_W", "total_efficiency"}
    assert shared <= set(budget.columns) and shared <= set(pair.budget.columns)
    parts = ["power_loss_W", "gear_no_load_W", "bearings_no_load_W", "bearings_load_W", "seals_W"]
    for (_, b), (_, r) in zip(budget.iterrows(), records.iterrows()):
        total = sum(b[p] for p in parts)
        assert abs(total - b["total_loss_W"]) <= 1e-9 * b["total_loss_W"]
        if r["flow"] == "drive" and not r["both_ends_deliver"]:
            loss = r["input_power_W"] - r["output_power_W"]
            assert abs(loss - b["total_loss_W"]) <= 1e-9 * abs(r["input_power_W"])
    assert any(c.startswith("bearing_motor_1_") for c in budget.columns)
    assert set(budget["label"]) == set(drive.data["laws"])
    efficiency = drive.efficiency
    assert {"first_mesh_efficiency", "second_mesh_efficiency", "total_efficiency", "label"} <= set(efficiency.columns)
    assert (efficiency["total_efficiency"] == records["efficiency"]).all()


def test_thermal_and_duty_cycle_tables_serve_a_pair_and_a_drive():
    """`thermal`, `heat_balance` and `duty_cycle` read a pair's and a drive's report alike (the same report types,
    the same columns): every balance at θ* gives off what it loses (1e-9) by paths that add up
    (1e-9); the EV reducer's drive rows carry their ratings (691.8 N·m at 500 rpm out, 36.22 kW);
    the duty cycle's steps add up to its totals (1e-9)."""
    drive = gearloss.Report.from_folder(ROOT / "reports/two_stage_ev_reducer")
    pair = gearloss.Report.from_folder(ROOT / "reports/fzg_c14_gearbox_thermal")
    for report in (drive, pair):
        thermal = report.thermal
        assert len(thermal) == len(report.data["thermal"]) > 0
        assert list(thermal.columns) == list(pair.thermal.columns)
        paths = thermal[[f"dissipation_{k}_W" for k in ("convection", "radiation", "foundation", "cooler")]].sum(axis=1)
        assert ((paths - thermal["dissipation_total_W"]).abs() <= 1e-9 * thermal["dissipation_total_W"]).all()
        settled = thermal[thermal["oil_temperature_K"].notna()]
        assert len(settled) > 0
        assert ((settled["power_loss_W"] - settled["dissipation_total_W"]).abs() <= 1e-9 * settled["power_loss_W"]).all()
        duty = report.duty_cycle
        assert list(duty.columns) == list(pair.duty_cycle.columns) and len(duty) > 0
        totals = report.data["duty_cycle"]
        for column, key in (("energy_lost_J", "energy_lost"), ("energy_dissipated_J", "energy_dissipated")):
            total = totals[key]["value"]
            assert abs(duty[column].sum() - total) <= 1e-9 * total
    rated = drive.thermal[drive.thermal["point"] == "T_out = 150 N·m, n_out = 500 rpm"].iloc[0]
    assert round(rated["thermal_rating_N_m"], 1) == 691.8 and round(rated["thermal_rating_W"] / 1e3, 2) == 36.22
    assert len(pair.duty_cycle) == 9 and len(drive.duty_cycle) == 4
    # The heat balance's curve: P_V − P_Q changes sign where the located θ* is (the curve is for
    # the plot; θ* itself is located, not read from it).
    for report in (drive, pair):
        curve = report.heat_balance
        assert list(curve.columns) == ["oil_temperature_K", "power_loss_W", "dissipation_W"] and len(curve) == 120
        theta = report.data["heat_balance"]["oil_temperature"]["value"]
        gap = curve["power_loss_W"] - curve["dissipation_W"]
        below, above = curve[curve["oil_temperature_K"] < theta], curve[curve["oil_temperature_K"] > theta]
        assert (gap[below.index] > 0).all() and gap[above.index[0]] < 0


def test_a_map_is_a_table_of_a_pair_and_of_a_drive():
    """`map` reads a drive's loss_map.csv, a scene of one pair's (its one-stage drive's) too: a row
    per grid point, law and formulation, with the whole loss and η; the drive's cells are
    report.json's (1e-9: the CSV holds 10 digits)."""
    drive = gearloss.Report.from_folder(ROOT / "reports/two_stage_ev_reducer")
    pair = gearloss.Report.from_folder(ROOT / "reports/fzg_c14_gearbox")
    for report in (drive, pair):
        assert {"law", "formulation", "total_loss_W", "total_efficiency"} <= set(report.map.columns)
    table, maps = drive.map, drive.data["maps"]
    assert len(table) == sum(len(m["torques"]) * len(m["speeds_rpm"]) for m in maps)
    first = maps[0]
    cells = table[(table["law"] == first["law"]) & (table["formulation"] == first["formulation"])]
    losses = [v for row in first["loss"] for v in row]
    assert len(cells) == len(losses)
    for a, b in zip(cells["total_loss_W"], losses):
        assert abs(a - b) <= 1e-9 * abs(b)
    assert len(pair.map) == 40 * 40 * 4


def test_a_drives_dynamics_are_its_stage_meshes():
    """A drive's `dynamics` are the dynamics rows of every stage mesh its analyses ran as a pair
    alone, keyed by stage, mesh and the drive's point; each is that mesh's own report's table
    (`stage_pairs`), row for row."""
    drive = gearloss.run(scene(ROOT / "specs/ev_reducer_stage_meshes.gear"))
    pairs = drive.stage_pairs
    assert set(pairs) == {r["folder"] for r in drive.data["stage_pairs"] if r.get("folder")} and len(pairs) == 4
    dynamics = drive.dynamics
    assert list(dynamics.columns[:3]) == ["stage", "mesh", "drive_point"]
    assert len(dynamics) == sum(len(p.dynamics) for p in pairs.values()) > 0
    for row in drive.data["stage_pairs"]:
        own = pairs[row["folder"]].dynamics
        mine = dynamics[(dynamics["stage"] == row["stage"]) & (dynamics["drive_point"] == row["point"])]
        pandas.testing.assert_frame_equal(mine.iloc[:, 3:].reset_index(drop=True), own)


def test_a_one_pair_drives_stage_is_its_pair_over_the_sweep(tmp_path):
    """A pair on a drive cycle analyses its stage as the pair alone over the scene's whole sweep
    (`stages/pair`, no drive point of its own): `dynamics` keys each row by its pair's own point,
    which is the drive's, and the rows are those of the same pair run alone (specs/fzg_dynamics.gear:
    ρ and the dynamic factor to 1e-12)."""
    text = (ROOT / "specs/fzg_dynamics.gear").read_text()
    text = text.replace(
        'scene "FZG type C dynamics" {',
        'scene "FZG C dynamics on a cycle" {\n'
        '    lubricant "oil" { dynamic_viscosity = 95 mPa*s  density = 880 kg/m^3  pressure_viscosity = 2e-8 1/Pa }\n'
        '    vehicle "car" { mass = 1976 kg  rotating_mass_factor = 1.07  wheel_radius = 0.335 m\n'
        '        road_load(f0 = 130 N, f1 = 1.2 N*s/m, f2 = 0.36 N*s^2/m^2)  final_ratio = 3.9 }\n'
        f'    drive_cycle "UDDS" {{ trace = "{(ROOT / "specs/cycles/udds.csv").as_posix()}" }}\n'
        "    friction { coulomb(mu = 0.08) }",
    )
    text = text.replace("rpm\n    }", "rpm\n        oil_temperature = 80 degC\n    }", 1)
    text = text[: text.index("    analyses {")] + "    analyses { efficiency(formulations = [external])  drive_cycle  dynamics }\n}\n"
    path = tmp_path / "cycle.gear"
    path.write_text(text)
    drive = gearloss.run(gearloss.Scene.from_file(path))
    (row,) = drive.data["stage_pairs"]
    assert row["folder"] == "stages/pair" and "point" not in row
    dynamics = drive.dynamics
    own = drive.stage_pairs["stages/pair"].dynamics
    assert len(dynamics) == len(own) == 6 * 3
    assert list(dynamics["drive_point"]) == list(own["point"])
    alone = gearloss.run(scene(ROOT / "specs/fzg_dynamics.gear")).dynamics
    numbers = [c for c in alone.columns if alone[c].dtype.kind == "f"]
    assert numbers
    for c in numbers:
        for x, y in zip(dynamics[c], alone[c]):
            assert x == y or abs(x - y) <= 1e-12 * max(abs(x), abs(y)), c


def test_pair_is_the_scenes_pair_however_it_ran():
    """`pair` is a pair's report itself, the one-pair drive's `stages/pair` report for a scene of
    one pair (on a drive cycle or not: its efficiency table the pair's own, a row per point, law and
    formulation), and a LookupError naming `stage_pairs` for a drive of several stages."""
    alone = gearloss.run(scene(ROOT / "specs/fzg_type_c.gear")).pair
    assert alone.pair is alone and len(alone.efficiency) == 2 * 3 * 2 * 2
    cycle = gearloss.run(scene(ROOT / "tests/specs/ok/cycle_pair_udds.gear"))
    pair = cycle.pair
    assert pair.data["geometry"] and len(pair.efficiency) == len(cycle.drive_records) == 4
    assert set(pair.efficiency["pinion_torque_N_m"]) == {20.0, 100.0}
    drive = gearloss.run(scene(ROOT / "specs/ev_two_stage_reducer.gear"))
    try:
        drive.pair
    except LookupError as e:
        assert "stage_pairs" in str(e)
    else:
        raise AssertionError("a drive of two stages has no one pair")


def test_one_pair_on_a_drive_cycle_is_a_one_stage_drive():
    """One pair with a vehicle runs as its one-stage drive: its records are a drive's (stage `pair`
    from `pinion_shaft` to `wheel_shaft`), its cycle a table, and its four points' P_in are
    T_in ω_in as written (1e-9)."""
    report = gearloss.run(scene(ROOT / "tests/specs/ok/cycle_pair_udds.gear"))
    records = report.records
    assert len(records) == 4 and set(report.stages["stage"]) == {"pair"}
    assert set(report.shafts["shaft"]) == {"pinion_shaft", "wheel_shaft"}
    for _, r in records.iterrows():
        p_in = r["input_torque_N_m"] * r["input_speed_rpm"] * 3.141592653589793 / 30.0
        assert abs(p_in - r["input_power_W"]) <= 1e-9 * abs(p_in)
    assert len(report.cycle) > 1000


def test_from_folder_of_a_missing_or_foreign_folder(tmp_path):
    with pytest.raises(FileNotFoundError, match="does not exist"):
        gearloss.Report.from_folder(tmp_path / "nope")
    (tmp_path / "empty").mkdir()
    with pytest.raises(FileNotFoundError, match="no report.json"):
        gearloss.Report.from_folder(tmp_path / "empty")
    (tmp_path / "file").write_text("x")
    with pytest.raises(NotADirectoryError):
        gearloss.Report.from_folder(tmp_path / "file")


def test_write_errors_are_the_os_error_of_their_cause(tmp_path):
    """A folder that cannot be made (its parent is a file) is `NotADirectoryError`; a read-only
    folder `PermissionError` (skipped as root, whom permissions do not stop)."""
    report = gearloss.run(scene(ROOT / "specs/fzg_type_c.gear"))
    (tmp_path / "a_file").write_text("x")
    with pytest.raises(NotADirectoryError):
        report.write(tmp_path / "a_file" / "under")
    if os.geteuid() != 0:
        ro = tmp_path / "ro"
        ro.mkdir()
        ro.chmod(0o500)
        with pytest.raises(PermissionError):
            report.write(ro)


def test_a_run_lives_on_disk_until_its_report_goes(tmp_path):
    """`run` keeps its folder in a temporary folder while the report lives, reads files when asked,
    and removes it with the report."""
    import gc

    report = gearloss.run(scene(ROOT / "specs/fzg_type_c.gear"))
    root = report._files.root
    assert (root / "report.json").is_file() and report.data["title"] == "FZG type C"
    runs_parent = root.parent
    del report
    gc.collect()
    assert not runs_parent.exists()


def test_dask_on_a_scene_of_a_drive_cycle_only_runs_it_whole():
    import gearloss.dask

    s = scene(ROOT / "specs/ev_reducer_wltc.gear")
    assert gearloss._native.operating_points(s.name, s.text) == 0
    report = gearloss.dask.run(s, shards=4)
    assert len(report.cycle) > 0
