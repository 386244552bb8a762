"""gearloss from Python: write, vary and run a scene, read every result as data.

The same library as the ``gearloss`` command runs underneath (the computation releases the GIL):

>>> import gearloss
>>> scene = gearloss.Scene.from_file("specs/fzg_type_c.gear")
>>> scene.title
'FZG type C'
>>> report = gearloss.run(scene.replace(pinion_speed="[1000, 2000] rpm"))
>>> report.data["title"]
'FZG type C'

A scene of one pair runs as its one-stage drive: ``report`` is the drive's (power at both ends,
losses part by part), ``report.pair`` the pair's own report (``stages/pair``):

>>> sorted(report.pair.efficiency["pinion_speed_rad_s"].round(3).unique().tolist())
[104.72, 209.44]
>>> len(report.efficiency) == len(report.pair.efficiency)
True

A scene that does not lower raises :class:`SceneError` with the CLI's diagnostics:

>>> try:
...     gearloss.Scene('scene "x" { gears { module = 4.5 kg } }', name="bad.gear")
... except gearloss.SceneError as e:
...     [(d["line"], d["column"], d["message"]) for d in e.diagnostics if d["kind"] == "WrongDimension"]
[(1, 34, '`module` expects a length, but `kg` is a mass')]
"""

from __future__ import annotations

import io
import json
import os
import pathlib
import shutil
import tempfile
import weakref
from collections.abc import Mapping
from typing import Iterable, Optional, Tuple, Union

from . import _native
from ._native import RexsError, RunError, SceneError

__all__ = ["Scene", "Report", "run", "merge", "SceneError", "RunError", "RexsError"]


class Scene:
    """A checked scene: its text, the name errors and relative paths refer to, its title.

    ``Scene(text, name=...)`` checks the text (a bad scene raises :class:`SceneError`);
    files the scene names (stiffness tables) are read relative to the folder of ``name``.

    >>> Scene.from_file("specs/fzg_type_c.gear").name
    'specs/fzg_type_c.gear'
    """

    def __init__(self, text: str, name: str = "scene.gear") -> None:
        self.title: str = _native.check(name, text)
        self.text = text
        self.name = name
        self.warnings: list = []

    @classmethod
    def from_file(cls, path: Union[str, os.PathLike]) -> "Scene":
        """Reads and checks a ``.gear`` file, as the CLI reads it: a regular file of at most 16 MiB
        (``/dev/zero``, a pipe or a folder raise ``OSError`` before anything is read), UTF-8 (the
        first bad byte located), line ends kept so that every column is the CLI's."""
        p = os.fspath(path)
        return cls(_native.read_scene(p), name=p)

    @classmethod
    def from_rexs(cls, path: Union[str, os.PathLike]) -> "Scene":
        """Imports a REXS gear-unit model (``.rexs`` XML, ``.rexsj`` JSON or ``.rexsz`` zip), as
        ``gearloss import`` does, and checks the scene it gives: ``.text`` is the commented scene,
        ``.warnings`` what the model has that gearloss does not use and what the import chose; a
        model that cannot be imported raises :class:`RexsError` (``.component``, ``.hint``)."""
        p = os.fspath(path)
        text, warnings = _native.import_rexs(p)
        scene = cls(text, name=os.path.splitext(p)[0] + ".gear")
        scene.warnings = list(warnings)
        return scene

    def replace(self, **values: str) -> "Scene":
        """A new scene with values of its ``operating`` block replaced (or added), written as in a
        scene, units and all, and checked like the text:

        >>> s = Scene.from_file("specs/fzg_type_c.gear")
        >>> s.replace(pinion_torque="300 N*m", pinion_speed="100..3000 rpm count 30").title
        'FZG type C'
        """
        pairs = [(key, _value_text(key, value)) for key, value in values.items()]
        return Scene(_native.replace(self.name, self.text, pairs), name=self.name)

    def __repr__(self) -> str:
        return f"Scene({self.title!r}, name={self.name!r})"


def _value_text(key: str, value) -> str:
    """A replaced value as scene text. A bare number is written as the scene would read it (NaN,
    infinities and signs are then said by the check, before the missing unit); anything else must
    be text, units and all."""
    if isinstance(value, bool) or not isinstance(value, (str, int, float)):
        raise TypeError(f"{key}: give the value as scene text, units and all, e.g. {key}=\"300 N*m\" (got {value!r})")
    if isinstance(value, float):
        if value != value:
            return "NaN"
        if value in (float("inf"), float("-inf")):
            return "inf" if value > 0 else "-inf"
        return repr(value)
    return str(value)


def _shard(shard: Union[None, str, Tuple[int, int]]) -> Optional[str]:
    """A shard as the text ``K/N`` the library validates (as ``gearloss run --shard`` does: 1 ≤ K ≤
    N ≤ 1 000 000, else ``ValueError``)."""
    if shard is None:
        return None
    if isinstance(shard, tuple):
        if len(shard) != 2 or any(isinstance(x, bool) or not isinstance(x, int) for x in shard):
            raise ValueError(f"shard: give (K, N) with whole numbers 1 ≤ K ≤ N, e.g. (2, 4) (got {shard!r})")
        return f"{shard[0]}/{shard[1]}"
    if not isinstance(shard, str):
        raise ValueError(f"shard: give \"K/N\" or (K, N), e.g. \"2/4\" (got {shard!r})")
    return shard


def _records(records) -> Optional[str]:
    if records is None or isinstance(records, str):
        return records
    return ",".join(records)


def run(scene: Scene, shard: Union[None, str, Tuple[int, int]] = None, records=None) -> "Report":
    """Runs the scene as ``gearloss run`` does (``shard="K/N"`` or ``(K, N)``: that share of its
    operating points, as ``gearloss run --shard K/N``, validated as the CLI validates it; ``records``:
    the record files, a list or a comma-separated text of ``csv``, ``jsonl``, ``parquet`` as
    ``--records`` takes them, default CSV and JSON Lines) and returns the report.

    The report folder is written to a temporary folder that lives as long as the returned
    :class:`Report` (removed when it is garbage-collected): a file is read when it is asked for, so a
    sweep of a million points costs Python no more memory than the table it reads. Ctrl-C stops the
    run within a block of points and raises ``KeyboardInterrupt``."""
    tmp = tempfile.mkdtemp(prefix="gearloss-run-")
    try:
        path = _native.run_to(scene.name, scene.text, tmp, _shard(shard), _records(records))
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        raise
    return Report._temporary(pathlib.Path(path), tmp)


def merge(folders: Iterable[Union[str, os.PathLike]]) -> "Report":
    """Merges shard folders as ``gearloss merge`` does (the merged folder kept on disk as
    :func:`run` keeps its own)."""
    tmp = tempfile.mkdtemp(prefix="gearloss-merge-")
    try:
        path = _native.merge_to([os.fspath(f) for f in folders], tmp)
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        raise
    return Report._temporary(pathlib.Path(path), tmp)


class _Folder(Mapping):
    """A report folder's files by their path inside it, read from disk when one is asked for."""

    def __init__(self, root: pathlib.Path) -> None:
        self.root = root
        self._names = sorted(p.relative_to(root).as_posix() for p in root.rglob("*") if p.is_file())
        self._known = set(self._names)

    def __getitem__(self, name: str) -> bytes:
        if name not in self._known:
            raise KeyError(name)
        return (self.root / name).read_bytes()

    def __iter__(self):
        return iter(self._names)

    def __len__(self) -> int:
        return len(self._names)


class Report:
    """A report folder in memory: ``report.json`` as ``data``, the records as pandas tables, the
    plots as SVG text, ``report.md``; ``write`` puts the folder on disk as ``gearloss run`` does.

    The tables keep the column names of ``records.csv``, whose units are SI and part of the name
    (``pinion_torque_N_m``, ``power_loss_W``).
    """

    def __init__(self, name: str, files: Union[Iterable[Tuple[str, bytes]], Mapping]) -> None:
        self.name = name
        self._files: Mapping = files if isinstance(files, _Folder) else dict(files)
        self._keep = None

    @classmethod
    def from_folder(cls, path: Union[str, os.PathLike]) -> "Report":
        """Opens a report folder that ``gearloss run`` (or ``write``) wrote; its files are read when
        asked for. A path that is not a folder raises ``FileNotFoundError`` (``NotADirectoryError``
        for a file), a folder without ``report.json`` or ``shard.json`` ``FileNotFoundError`` naming
        what it lacks."""
        root = pathlib.Path(path)
        if not root.exists():
            raise FileNotFoundError(f"no report folder {os.fspath(path)!r}: it does not exist")
        if not root.is_dir():
            raise NotADirectoryError(f"{os.fspath(path)!r} is a file, not a report folder")
        if not (root / "report.json").is_file() and not (root / "shard.json").is_file():
            raise FileNotFoundError(
                f"{os.fspath(path)!r} is not a report folder: it holds no report.json (nor a shard's shard.json)"
            )
        return cls(root.name, _Folder(root))

    @classmethod
    def _temporary(cls, root: pathlib.Path, tmp: str) -> "Report":
        """A report in a temporary folder, removed when the report is garbage-collected."""
        report = cls(root.name, _Folder(root))
        weakref.finalize(report, shutil.rmtree, tmp, True)
        return report

    def _source(self, name: str):
        """A file as pandas reads it: its path on disk, or its bytes."""
        if isinstance(self._files, _Folder):
            return self._files.root / name
        return io.BytesIO(self._files[name])

    def _shape(self) -> str:
        """``"drive"`` (a drive of several stages), ``"pair"``, ``"runs"`` (several oil
        temperatures) or ``"shard"``."""
        if any(f.startswith("drive_records.") for f in self._files):
            return "drive"
        if any(f.startswith("records.") for f in self._files):
            return "pair"
        if "shard.json" in self._files:
            return "shard"
        if "report.json" in self._files and "runs" in self.data:
            return "runs"
        return "drive" if "report.json" in self._files and "stages" in self.data else "pair"

    def _table_of(self, table: str, shape: str) -> None:
        """Raises ``LookupError`` where ``table`` is not a table of this report's kind."""
        mine = self._shape()
        if mine == shape or mine == "shard":
            return
        if mine == "runs":
            raise LookupError(
                f"`{table}` is a table of one run; this report holds runs at several oil temperatures: "
                f"read it of one of them, report.runs[name].{table} ({', '.join(self.runs)})"
            )
        tables = _TABLES[mine]
        raise LookupError(
            f"`{table}` is a table of {_SHAPES[shape]}, and this report is of {_SHAPES[mine]}: "
            f"its tables are {', '.join(tables)}"
        )

    @property
    def files(self) -> list:
        """The files of the folder, by path inside it."""
        return sorted(self._files)

    @property
    def data(self) -> dict:
        """``report.json``, parsed."""
        return json.loads(self._files["report.json"])

    @property
    def runs(self) -> Dict[str, "Report"]:
        """A scene at several oil temperatures: the report of each, by its folder's name."""
        names = sorted({f.split("/")[0] for f in self._files if "/" in f})
        return {n: self._sub(n) for n in names}

    @property
    def records(self):
        """The records as a pandas DataFrame (every operating point, every law and formulation):
        ``records.csv``, or ``records.parquet`` when the run wrote Parquet only (the same columns
        and values, then each law parameter's ``param_…`` column; reading it needs pyarrow). Of a
        drive (every scene run: one of one pair runs as its one-stage drive, whose pair's own
        records are ``report.pair.records``) its rows, :attr:`drive_records`."""
        import pandas

        if self._shape() == "drive":
            return self.drive_records
        self._table_of("records", "pair")
        if "records.csv" in self._files:
            return pandas.read_csv(self._source("records.csv"))
        if "records.parquet" in self._files:
            return pandas.read_parquet(self._source("records.parquet"))
        return pandas.DataFrame()

    def _kind(self, kind: str):
        self._table_of({"efficiency": "efficiency", "dynamics": "dynamics"}[kind], "pair")
        r = self.records
        if r.empty:
            return r
        return r[r["kind"] == kind].dropna(axis=1, how="all").reset_index(drop=True)

    @property
    def efficiency(self):
        """The efficiency rows: per point, law and formulation the mean efficiency, its error and the
        mesh's power loss (a pair alone's: the whole budget is its one-stage drive's). Of a drive:
        per operating point, law and formulation (a record row) both ends' torque, speed and power,
        each stage's η_mesh (``<stage>_mesh_efficiency``) and the box's η (``total_efficiency``)."""
        if self._shape() == "drive":
            r = self.drive_records
            if r.empty:
                return r
            ends = [c for c in r.columns if c.startswith(("input_", "output_"))]
            stages = {c: c[len("stage_") :] for c in r.columns if c.startswith("stage_") and c.endswith("_mesh_efficiency")}
            table = r[_DRIVE_KEYS + ends + list(stages) + ["efficiency"]].rename(columns=stages)
            return self._drive_labelled(table.rename(columns={"efficiency": "total_efficiency"}))
        return self._kind("efficiency")

    @property
    def budget(self):
        """The loss budget (W) of a drive (every scene's, a scene of one pair's its one-stage
        drive's): a row per record row, keyed by ``torque_index``, ``speed_index``, ``law_index``,
        ``label`` and ``formulation``, with every mesh's loss (``power_loss_W``), gears without
        load, bearings, seals, ``total_loss_W`` and ``total_efficiency``, and each bearing place's
        loads and losses (``bearing_<shaft>_<n>_…``). Of a pair alone (a stage mesh's report,
        ``.pair``): empty, its budget is the drive's."""
        if self._shape() == "drive":
            r = self.drive_records
            if r.empty:
                return r
            parts = {
                "meshes_W": "power_loss_W",
                "gear_no_load_W": "gear_no_load_W",
                "bearings_no_load_W": "bearings_no_load_W",
                "bearings_load_W": "bearings_load_W",
                "seals_W": "seals_W",
                "total_W": "total_loss_W",
            }
            bearings = [c for c in r.columns if c.startswith("bearing_")]
            table = r[_DRIVE_KEYS + list(parts) + bearings + ["efficiency"]]
            return self._drive_labelled(table.rename(columns={**parts, "efficiency": "total_efficiency"}))
        self._table_of("budget", "pair")
        import pandas

        return pandas.DataFrame()

    def _drive_labelled(self, table):
        """A drive's table with each row's law as the report labels it (``label``) beside its index."""
        labels = self.data.get("laws", [])
        table = table.reset_index(drop=True)
        table.insert(_DRIVE_KEYS.index("law_index") + 1, "label", [labels[int(i)] for i in table["law_index"]])
        return table

    @property
    def dynamics(self):
        """The dynamics rows: per point and formulation ρ, DTE and the dynamic factor. Of a drive:
        those of every stage mesh its ``analyses`` ran as a pair alone (:attr:`stage_pairs`), with
        the mesh's ``stage``, ``mesh`` (a planetary stage's) and the drive's operating point
        (``drive_point``, 1-based; a one-pair drive's stage, analysed over the whole sweep, gives its
        pair's own points, which are the drive's) in front; empty where no stage mesh ran dynamics."""
        if self._shape() == "drive":
            import pandas

            parts = []
            for row in self.data.get("stage_pairs", []):
                folder = row.get("folder")
                if not folder:
                    continue
                table = self._sub(folder).dynamics
                # A one-pair drive's stage analysed over the whole sweep has no drive point of its
                # own: its pair's points are the drive's (the same grid, torque-major).
                point = row.get("point")
                if point is None and "point" in table.columns:
                    point = table["point"]
                for k, (name, value) in enumerate(
                    [("stage", row["stage"]), ("mesh", row.get("mesh", "")), ("drive_point", point)]
                ):
                    table.insert(k, name, value)
                parts.append(table)
            return pandas.concat(parts, ignore_index=True) if parts else pandas.DataFrame()
        return self._kind("dynamics")

    @property
    def thermal(self):
        """The thermal balance of every shown point, law and formulation (report.json's
        ``thermal``) of a drive (a scene of one pair's its one-stage drive's; a pair alone's report
        has none): ``point`` (the row in words), ``law``, ``label``, ``formulation``, the torque and
        speed at the given ends, θ* (``oil_temperature_K``, empty without a balance), ``status``, P_V at
        θ* and what the housing gives off there by path (W), ``heat_transfer_coefficient_W_m2_K``
        and both ratings (N·m and W; empty in coast or where none is found); empty without a
        thermal balance."""
        import pandas

        self._table_of("thermal", self._shape() if self._shape() in ("pair", "drive") else "pair")
        q = lambda x: None if x is None else x["value"]  # noqa: E731
        rows = []
        for t in self.data.get("thermal", []):
            d = t["dissipation"]
            ratings = [(t.get(k) or {}) for k in ("thermal_rating", "thermal_rating_95")]
            rows.append(
                {
                    "point": t.get("point", t["case"] + 1),
                    "law": t["law"],
                    "label": t["label"],
                    "formulation": t["formulation"],
                    "torque_N_m": q(t["pinion_torque"]),
                    "speed_rad_s": q(t["pinion_speed"]),
                    "oil_temperature_K": q(t.get("oil_temperature")),
                    "status": t["status"],
                    "power_loss_W": q(t["power_loss"]),
                    **{f"dissipation_{k}_W": q(d[k]) for k in ("convection", "radiation", "foundation", "cooler", "total")},
                    "heat_transfer_coefficient_W_m2_K": q(t["heat_transfer_coefficient"]),
                    "thermal_rating_N_m": q(ratings[0].get("torque")),
                    "thermal_rating_W": q(ratings[0].get("power")),
                    "thermal_rating_95_N_m": q(ratings[1].get("torque")),
                    "thermal_rating_95_W": q(ratings[1].get("power")),
                }
            )
        return pandas.DataFrame(rows)

    @property
    def map(self):
        """The efficiency map's cells as a DataFrame: ``loss_map.csv`` (per grid point, law and
        formulation the torque and speed at the ends the map is given at — ``output_torque_N_m``,
        a scene of one pair's ``pinion_torque_N_m`` —, each loss part, ``total_loss_W``,
        ``total_efficiency`` and, of one pair, ``pinion_efficiency``), or the ``efficiency_map.csv``
        of a pair's folder written before a pair ran as its one-stage drive; SI units in the
        column names; empty without a map."""
        import pandas

        self._table_of("map", self._shape() if self._shape() in ("pair", "drive") else "pair")
        for name in ("efficiency_map.csv", "loss_map.csv"):
            if name in self._files:
                return pandas.read_csv(self._source(name))
        return pandas.DataFrame()

    @property
    def heat_balance(self):
        """The heat balance's curve (report.json's ``heat_balance``: the drive's first row, a
        scene of one pair's one-stage drive's too): ``oil_temperature_K`` from ambient to
        200 °C, the losses ``power_loss_W`` and what the housing gives off ``dissipation_W``
        there; the located balance θ* is ``data["heat_balance"]["oil_temperature"]``. Empty
        without one."""
        import pandas

        self._table_of("heat_balance", self._shape() if self._shape() in ("pair", "drive") else "pair")
        h = self.data.get("heat_balance")
        if not h:
            return pandas.DataFrame()
        return pandas.DataFrame(
            {"oil_temperature_K": h["temperature"], "power_loss_W": h["power_loss"], "dissipation_W": h["dissipation"]}
        )

    @property
    def duty_cycle(self):
        """The duty cycle's steps (report.json's ``duty_cycle``), a pair's and a drive's alike: each
        step's ``label`` as written, ``duration_s``, torque and speed, and where computed the
        transient's θ at its end (K), the energy lost and given off in it (J), and P_V and the energy
        at the scene's fixed oil temperature (W, J); empty without a duty cycle."""
        import pandas

        self._table_of("duty_cycle", self._shape() if self._shape() in ("pair", "drive") else "pair")
        duty = self.data.get("duty_cycle") or {"steps": []}
        q = lambda x: None if x is None else x["value"]  # noqa: E731
        keys = {
            "oil_temperature_end": "oil_temperature_end_K",
            "energy_lost": "energy_lost_J",
            "energy_dissipated": "energy_dissipated_J",
            "power_loss_fixed": "power_loss_fixed_W",
            "energy_lost_fixed": "energy_lost_fixed_J",
        }
        rows = [
            {
                "step": k + 1,
                "label": s["label"],
                "duration_s": q(s["duration"]),
                "torque_N_m": q(s["pinion_torque"]),
                "speed_rad_s": q(s["pinion_speed"]),
                **{name: q(s.get(key)) for key, name in keys.items()},
            }
            for k, s in enumerate(duty["steps"])
        ]
        return pandas.DataFrame(rows)

    @property
    def stage_pairs(self) -> Dict[str, "Report"]:
        """A drive's stage meshes its ``analyses`` ran as pairs alone: each one's report (a pair's,
        with all of a pair's tables) by its folder, ``stages/<stage>[_<mesh>]_point_<n>``; a mesh
        listed as not run (report.json's ``stage_pairs[].not_run`` says why) has none."""
        self._table_of("stage_pairs", "drive")
        return {r["folder"]: self._sub(r["folder"]) for r in self.data.get("stage_pairs", []) if r.get("folder")}

    @property
    def pair(self) -> "Report":
        """The report of the scene's one pair, with all of a pair's tables: its pair's own report
        (``stages/pair``, over the scene's whole sweep) for a scene of one pair, which runs as its
        one-stage drive (on a drive cycle or not); this report itself where it is a pair's (a stage
        folder's, a report folder written before). ``LookupError`` for a drive of several stages (its stage meshes are
        :attr:`stage_pairs`) and for a report of several oil temperatures (``runs[name].pair``)."""
        shape = self._shape()
        if shape in ("pair", "shard"):
            return self
        sweep = [r for r in self.data.get("stage_pairs", []) if r.get("folder") and "point" not in r]
        if shape == "drive" and sweep:
            return self._sub(sweep[0]["folder"])
        if shape == "runs":
            raise LookupError(
                f"this report holds runs at several oil temperatures: read the pair of one of them, "
                f"report.runs[name].pair ({', '.join(self.runs)})"
            )
        raise LookupError(
            "`pair` is the report of a scene of one pair; this drive has several stages (or its one stage was not "
            "analysed over its sweep): its stage meshes analysed as pairs are report.stage_pairs"
        )

    def _sub(self, folder: str) -> "Report":
        """The report in ``folder`` inside this one's."""
        if isinstance(self._files, _Folder):
            sub = Report(folder, _Folder(self._files.root / folder))
            sub._keep = self  # the temporary folder lives as long as a report read from it
            return sub
        prefix = folder + "/"
        return Report(folder, [(f[len(prefix) :], b) for f, b in self._files.items() if f.startswith(prefix)])

    @property
    def drive_records(self):
        """``drive_records.csv`` (or ``drive_records.parquet``, else ``drive_records.jsonl``, when
        the run wrote no CSV: the same columns and values) of a drive of several stages as a
        DataFrame: a row per operating point, law and formulation with the ends' torque, speed and
        power, every loss part, η, the passes, and each stage's, bearing place's and shaft's
        columns; empty for one pair."""
        import pandas

        self._table_of("drive_records", "drive")
        if "drive_records.csv" in self._files:
            return pandas.read_csv(self._source("drive_records.csv"))
        if "drive_records.parquet" in self._files:
            frame = pandas.read_parquet(self._source("drive_records.parquet"))
            # The file holds `both_ends_deliver` as the CSV writes it (text `true`/`false`); the
            # DataFrame gives it as the CSV reader does, a bool.
            frame["both_ends_deliver"] = frame["both_ends_deliver"] == "true"
            return frame
        if "drive_records.jsonl" in self._files:
            frame = pandas.read_json(self._source("drive_records.jsonl"), lines=True, dtype=False, precise_float=True)
            frame["both_ends_deliver"] = frame["both_ends_deliver"] == "true"
            return frame
        return pandas.DataFrame()

    @property
    def cycle(self):
        """A drive cycle's ``cycle_records.csv`` as a DataFrame: a row per interval of the trace
        with its times (s), speeds (km/h), wheel force (N) and torque (N·m) and wheel and motor
        speeds (rpm) at its start and end, the motor's mean torque (N·m), the box's loss and each
        part (J) with the loss's error estimate, the motor's and the wheel's energy and what the
        brakes take (J), and with the sump's transient its temperature at the end (°C); empty
        without a drive cycle."""
        import pandas

        self._table_of("cycle", "drive")
        if "cycle_records.csv" not in self._files:
            return pandas.DataFrame()
        return pandas.read_csv(self._source("cycle_records.csv"))

    @property
    def stages(self):
        """Per record row and stage: the driving member, its torque, η_mesh, the mesh loss and the
        stage's no-load loss (W)."""
        self._table_of("stages", "drive")
        names = [s["name"] for s in self.data.get("stages", [])]
        cols = ["driving", "driving_torque_N_m", "mesh_efficiency", "mesh_loss_W", "no_load_W"]
        return _drive_long(self, "stage", names, cols, "stage")

    @property
    def planetary(self):
        """Per record row and planetary stage: its members' speeds (rpm) and torques (N·m), the
        rolling power P_w (W), η₀ and both meshes' η and loss (W), the planet bearing's load (N)
        and the planets' bearing and churning losses (W); empty without planetary stages."""
        names = [s["name"] for s in self.data.get("stages", []) if s.get("planetary")]
        cols = [
            "sun_speed_rpm", "sun_torque_N_m", "ring_speed_rpm", "ring_torque_N_m", "carrier_speed_rpm",
            "carrier_torque_N_m", "rolling_power_W", "basic_efficiency", "sun_planet_efficiency",
            "planet_ring_efficiency", "sun_planet_loss_W", "planet_ring_loss_W", "planet_bearing_load_N",
            "planet_bearings_W", "churning_W",
        ]
        self._table_of("planetary", "drive")
        return _drive_long(self, "stage", names, cols, "stage")

    @property
    def shafts(self):
        """Per record row and shaft: its speed (rpm, signed about +z), the torques it receives and
        passes on (N·m), its gears' no-load parts and its seals (W)."""
        self._table_of("shafts", "drive")
        names = [s["name"] for s in self.data.get("shafts", [])]
        cols = ["speed_rpm", "received_torque_N_m", "passed_torque_N_m", "gear_no_load_W", "seals_W"]
        return _drive_long(self, "shaft", names, cols, "shaft")

    @property
    def bearings(self):
        """Per record row and bearing place (``shaft_place``, the places numbered 1, 2, … along their shaft as the scene lists them): the
        radial and axial load per bearing (N) and the place's P_0 and P_1 (W)."""
        names = [f"{s['name']}_{i + 1}" for s in self.data.get("shafts", []) for i in range(len(s["bearings"]))]
        cols = ["radial_N", "axial_N", "no_load_W", "load_W"]
        self._table_of("bearings", "drive")
        return _drive_long(self, "bearing", names, cols, "place")

    @property
    def plots(self) -> list:
        """The names of the report's plots (``svg(name)`` reads one)."""
        return sorted(f for f in self._files if f.endswith(".svg"))

    def svg(self, name: str) -> str:
        """A plot's SVG text (``report.svg("contact_state")`` or ``"contact_state.svg"``); a name
        the report has no plot of raises ``KeyError`` listing the plots it has."""
        file = name if name.endswith(".svg") else name + ".svg"
        if file not in self._files:
            raise KeyError(f"no plot {file!r} in this report; its plots: {', '.join(self.plots) or 'none'}")
        return self._files[file].decode("utf-8")

    def markdown(self) -> str:
        """``report.md``."""
        return self._files["report.md"].decode("utf-8")

    def write(self, folder: Union[str, os.PathLike]) -> pathlib.Path:
        """Writes the report folder into ``folder`` as ``gearloss run --out folder`` does (the same
        writer): into a hidden temporary folder first, renamed into place, so it is never
        half-written; processes writing the same folder at once all succeed, the last one wins,
        and nothing else is left behind."""
        files = [(path, bytes(content)) for path, content in self._files.items()]
        return pathlib.Path(_native.write_folder(os.fspath(folder), self.name, files))

    def _repr_markdown_(self) -> str:
        return self.markdown() if "report.md" in self._files else f"report {self.name}"

    def __repr__(self) -> str:
        return f"Report({self.name!r}, {len(self._files)} files)"


_SHAPES = {"pair": "one gear pair", "drive": "a drive of several stages", "runs": "several oil temperatures"}
_TABLES = {
    "pair": ("records", "efficiency", "budget", "dynamics", "map", "thermal", "heat_balance", "duty_cycle"),
    "drive": (
        "records",
        "efficiency",
        "budget",
        "dynamics",
        "map",
        "thermal",
        "heat_balance",
        "duty_cycle",
        "drive_records",
        "stages",
        "stage_pairs",
        "shafts",
        "bearings",
        "planetary",
        "cycle",
    ),
    "runs": ("runs",),
}


# The columns that key a drive's record row: its index, the operating point's torque and speed
# indices, the law's index, the formulation and the power's flow.
_DRIVE_KEYS = ["row", "torque_index", "speed_index", "law_index", "formulation", "flow"]


def _drive_long(report: "Report", prefix: str, names, columns, key: str):
    """A long table from drive_records.csv's wide columns ``<prefix>_<name>_<column>``: a row per
    record row and name, keyed by the record's indices, law and formulation."""
    import pandas

    wide = report.drive_records
    keys = _DRIVE_KEYS
    parts = []
    for name in names:
        cols = {f"{prefix}_{name}_{c}": c for c in columns}
        part = wide[keys + list(cols)].rename(columns=cols)
        part.insert(len(keys), key, name)
        parts.append(part)
    if not parts:
        return pandas.DataFrame()
    return pandas.concat(parts, ignore_index=True).sort_values(["row", key], kind="stable").reset_index(drop=True)

