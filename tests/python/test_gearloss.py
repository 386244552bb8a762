"""The Python package against the CLI: the same reports, the same errors, the same shards merged.

Run from the repository root (``tests/python/run`` does): the scenes are read by their paths in
``specs/`` and ``tests/specs/``, and ``reports/`` holds what ``gearloss run`` wrote for each
``specs/`` scene (a Rust test keeps them current).
"""

import json
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
    """`run(...).data` is the CLI's report.json and `.records` its records.csv, for every scene."""
    report = gearloss.run(scene(path))
    folder = ROOT / "reports" / report.name
    assert json.loads((folder / "report.json").read_text()) == report.data
    if (folder / "records.csv").exists():
        pandas.testing.assert_frame_equal(report.records, pandas.read_csv(folder / "records.csv"))
    else:
        assert report.records.empty
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
    a = gearloss.run(replaced).efficiency
    b = gearloss.run(gearloss.Scene(by_hand, name=base.name)).efficiency
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
    for name in ("report.md", "report.json", "records.csv", "contact_state.svg"):
        assert (out / name).read_bytes() == (ROOT / "reports/fzg_type_c" / name).read_bytes(), name
    assert gearloss.Report.from_folder(out).data == report.data
    report.write(tmp_path)  # again, in place of the first
    assert sorted(p.name for p in tmp_path.iterdir()) == ["fzg_type_c"]


def test_tidy_tables():
    gearbox = gearloss.run(scene(ROOT / "specs/fzg_c14_gearbox.gear"))
    budget = gearbox.budget
    assert {"total_loss_W", "bearings_load_W", "seals_W", "label", "formulation"} <= set(budget.columns)
    # Every law and formulation (issue 46: it used to keep the first of each point only).
    assert len(budget) == len(gearbox.efficiency)
    keyed = budget.set_index(["point", "label", "formulation"])
    assert keyed.index.is_unique
    assert budget["label"].nunique() == 2 and budget["formulation"].nunique() == 2
    for _, row in budget.iterrows():
        parts = row["gear_no_load_W"] + row["bearings_no_load_W"] + row["bearings_load_W"] + row["seals_W"]
        assert abs(row["power_loss_W"] + parts - row["total_loss_W"]) <= 1e-9 * row["total_loss_W"]
    dynamics = gearloss.run(scene(ROOT / "specs/fzg_dynamics.gear")).dynamics
    assert {"spectral_radius", "pinion_speed_rad_s"} <= set(dynamics.columns) and len(dynamics) > 0
    assert gearloss.run(scene(ROOT / "specs/fzg_type_c.gear")).budget.empty


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
