#!/usr/bin/env python3
"""Writes the hand-made planetary REXS fixtures of tests/rexs/constructs/ (and two refusals in
tests/rexs/err/), each as XML (.rexs) and JSON (.rexsj) from one description here, so the two
formats carry the same model. Run from the repository root: python3 tests/rexs/constructs/planetary_fixtures.py

planetary_and_parallel: a spur planetary stage (sun 24, planets 3 x 24, ring 72, m 2 mm) whose
    ring is a part of the casing, its carrier on two cheeks with one catalogue bearing each and its
    planets on two needle roller bearings, followed by a parallel stage (20/60, m 3 mm) whose
    pinion sits on the carrier's far cheek: sun in at 3000 rpm and 100 N*m, the wheel's shaft out.
carrier_held: the same planetary stage with the carrier held by a coupling to the casing (a
    star stage) and the ring on the output shaft; the planets on one deep groove ball bearing.
err/compound_planetary_set: the first with a second ring meshing the planets.
floating_sun: the helical one with its sun's shaft on one bearing (the planets centre the sun).
helical_planetary: the first with a helix of 10 deg (the sun right hand, the planets left, the ring
    left), its ring's tip by the addendum rule.
"""

import json
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]


def num(x):
    return {"floating_point": float(x)}


def vec(*v):
    return {"floating_point_array": [float(a) for a in v]}


class Model:
    def __init__(self):
        self.components = []
        self.relations = []

    def comp(self, cid, kind, name, **attrs):
        self.components.append((cid, kind, name, attrs))
        return cid

    def rel(self, kind, **refs):
        self.relations.append((len(self.relations) + 1, kind, refs))

    def xml(self, version="1.4"):
        out = [
            '<?xml version="1.0" encoding="UTF-8"?>',
            f'<model applicationId="gearloss fixtures" applicationVersion="1" date="2026-11-29T00:00:00+01:00" version="{version}">',
            "  <relations>",
        ]
        for rid, kind, refs in self.relations:
            out.append(f'    <relation id="{rid}" type="{kind}">')
            for role, cid in refs.items():
                out.append(f'      <ref hint="{self.kind_of(cid)}" id="{cid}" role="{role}"/>')
            out.append("    </relation>")
        out.append("  </relations>")
        out.append("  <components>")
        for cid, kind, name, attrs in self.components:
            out.append(f'    <component id="{cid}" name="{name}" type="{kind}">')
            for aid, (unit, value) in attrs.items():
                if "floating_point_array" in value:
                    cells = "".join(f"<c>{a}</c>" for a in value["floating_point_array"])
                    out.append(f'      <attribute id="{aid}" unit="{unit}"><array>{cells}</array></attribute>')
                elif "boolean_array" in value:
                    cells = "".join(f"<c>{str(a).lower()}</c>" for a in value["boolean_array"])
                    out.append(f'      <attribute id="{aid}" unit="{unit}"><array>{cells}</array></attribute>')
                else:
                    v = next(iter(value.values()))
                    text = str(v).lower() if isinstance(v, bool) else str(v)
                    out.append(f'      <attribute id="{aid}" unit="{unit}">{text}</attribute>')
            out.append("    </component>")
        out.append("  </components>")
        out.append("</model>")
        return "\n".join(out) + "\n"

    def json(self, version="1.4"):
        model = {
            "version": version,
            "applicationId": "gearloss fixtures",
            "applicationVersion": "1",
            "date": "2026-11-29T00:00:00+01:00",
            "relations": [
                {
                    "id": rid,
                    "type": kind,
                    "refs": [{"id": cid, "role": role, "hint": self.kind_of(cid)} for role, cid in refs.items()],
                }
                for rid, kind, refs in self.relations
            ],
            "components": [
                {
                    "id": cid,
                    "name": name,
                    "type": kind,
                    "attributes": [dict({"id": aid, "unit": unit}, **value) for aid, (unit, value) in attrs.items()],
                }
                for cid, kind, name, attrs in self.components
            ],
        }
        return json.dumps({"model": model}, indent=2, ensure_ascii=False) + "\n"

    def kind_of(self, cid):
        return next(k for c, k, _, _ in self.components if c == cid)


def gear(m, cid, name, teeth, module, width, u, sv, helix=0.0, kind="cylindrical_gear"):
    return m.comp(
        cid,
        kind,
        name,
        number_of_teeth=("none", {"integer": teeth}),
        normal_module=("mm", num(module)),
        face_width=("mm", num(width)),
        helix_angle_reference_diameter=("deg", num(helix)),
        normal_pressure_angle=("deg", num(20)),
        addendum_modification_coefficient=("none", num(0)),
        u_coordinate_on_shaft=("mm", num(u)),
        support_vector=("mm", vec(*sv)),
    )


def shaft(m, cid, name, sv, **extra):
    return m.comp(cid, "shaft", name, support_vector=("mm", vec(*sv)), u_axis_vector=("mm", vec(1, 0, 0)), **extra)


def bearing(m, cid, name, designation, u, axial, kind="rolling_bearing_with_catalog_geometry", **extra):
    attrs = dict(
        u_coordinate_on_shaft_inner_side=("mm", num(u)),
        axial_force_absorption=("none", {"enum": axial}),
    )
    if designation:
        attrs["catalogue_designation"] = ("none", {"string": designation})
    attrs.update(extra)
    return m.comp(cid, kind, name, **attrs)


def output_shaft_parts(m, shaft, ids, designation, places, name):
    """The output shaft's two bearings (ids[0] locating at places[0], ids[1] at places[1]) and its
    load that transmits torque (ids[2])."""
    for cid, u, axial, end in zip(ids[:2], places, ("both_directions", "no_direction"), "AB"):
        bearing(m, cid, f"{name} {end}", designation, u, axial)
        m.rel("side", assembly=cid, inner_part=shaft, outer_part=2)
    m.comp(ids[2], "external_load", "Load", transmits_torque=("none", {"boolean": True}))
    m.rel("assembly", assembly=shaft, part=ids[2])


def unit(variant):
    """The model of `variant` (see the module's doc)."""
    m = Model()
    helix = 10.0 if variant in ("helical_planetary", "floating_sun") else 0.0
    m.comp(1, "gear_unit", "Planetary and parallel unit")
    m.comp(2, "gear_casing", "Casing", temperature_lubricant=("C", num(70)))
    m.comp(3, "lubricant", "ISO VG 150", viscosity_at_40_degree_celsius=("mm^2 / s", num(150)),
           viscosity_at_100_degree_celsius=("mm^2 / s", num(14.5)), density_at_15_degree_celsius=("kg / dm^3", num(0.89)))
    m.rel("reference", origin=2, referenced=3)
    m.comp(9, "planetary_stage", "Planetary stage")
    m.rel("assembly", assembly=1, part=9)
    # The sun's shaft: the input.
    shaft(m, 10, "Sun shaft", (0, 0, 0), rotational_speed=("1 / min", num(3000)), defines_speed=("none", {"boolean": True}))
    m.rel("central_shaft", planetary_stage=9, shaft=10)
    gear(m, 11, "Sun", 24, 2, 25, 60, (60, 0, 0), helix=helix)
    m.rel("assembly", assembly=10, part=11)
    bearing(m, 12, "Sun bearing A", "6206", 10, "both_directions")
    sun_bearings = (12,) if variant == "floating_sun" else (12, 13)
    if variant != "floating_sun":
        bearing(m, 13, "Sun bearing B", "6206", 110, "no_direction")
    for b in sun_bearings:
        m.rel("side", assembly=b, inner_part=10, outer_part=2)
    m.comp(14, "external_load", "Motor", torque_around_u_axis=("N m", num(100)),
           transmits_torque=("none", {"boolean": True}), defines_torque=("none", {"boolean": True}))
    m.rel("assembly", assembly=10, part=14)
    # The carrier on two cheeks.
    m.comp(30, "planet_carrier", "Carrier")
    m.rel("assembly", assembly=9, part=30)
    shaft(m, 31, "Carrier cheek 1", (0, 0, 0))
    shaft(m, 32, "Carrier cheek 2", (100, 0, 0))
    for s in (31, 32):
        m.rel("planet_carrier_shaft", planetary_stage=9, shaft=s)
        m.rel("assembly", assembly=30, part=s)
    # The ring: in the casing, or on the output shaft where the carrier is held.
    held_carrier = variant == "carrier_held"
    ring = gear(m, 40, "Ring", 72, 2, 25, 60, (60, 0, 0), helix=-helix + 0.0, kind="ring_gear")
    if held_carrier:
        shaft(m, 41, "Ring shaft", (0, 0, 0))
        m.rel("central_shaft", planetary_stage=9, shaft=41)
        m.rel("assembly", assembly=41, part=ring)
        output_shaft_parts(m, 41, (42, 43, 44), "6220", (20, 100), "Ring bearing")
        m.comp(33, "coupling", "Carrier to casing")
        m.rel("side", assembly=33, inner_part=31, outer_part=2)
    else:
        m.rel("assembly", assembly=2, part=ring)
        bearing(m, 34, "Carrier bearing A", "6212", 10, "both_directions")
        m.rel("side", assembly=34, inner_part=31, outer_part=2)
        bearing(m, 35, "Carrier bearing B", "6212", 0, "no_direction")
        m.rel("side", assembly=35, inner_part=32, outer_part=2)
    if variant == "compound_planetary_set":
        gear(m, 45, "Second ring", 72, 2, 25, 60, (60, 0, 0), kind="ring_gear")
        m.rel("assembly", assembly=2, part=45)
    # Three planets at 90°, 210° and 330°, each on its planet shaft, on a pin of the carrier.
    import math
    a = round(48 / math.cos(math.radians(helix)), 9)
    for j in range(3):
        ang = math.radians(90 + 120 * j)
        v, w = round(a * math.cos(ang), 9) + 0.0, round(a * math.sin(ang), 9) + 0.0
        ps, pin, pg = 50 + j, 60 + j, 70 + j
        shaft(m, ps, f"Planet shaft {j + 1}", (35, v, w))
        shaft(m, pin, f"Planet pin {j + 1}", (35, v, w))
        m.rel("planet_shaft", planetary_stage=9, shaft=ps)
        m.rel("planet_pin", planetary_stage=9, shaft=pin)
        m.rel("assembly", assembly=30, part=pin)
        gear(m, pg, f"Planet {j + 1}", 24, 2, 25, 25, (60, v, w), helix=-helix)
        m.rel("assembly", assembly=ps, part=pg)
        m.comp(100 + 10 * j, "cylindrical_stage", f"Sun-planet {j + 1}", center_distance=("mm", num(a)),
               common_face_width=("mm", num(25)))
        m.rel("assembly", assembly=9, part=100 + 10 * j)
        m.rel("stage", stage=100 + 10 * j, gear_1=11, gear_2=pg)
        m.comp(101 + 10 * j, "cylindrical_stage", f"Planet-ring {j + 1}", center_distance=("mm", num(-a)),
               common_face_width=("mm", num(25)))
        m.rel("assembly", assembly=9, part=101 + 10 * j)
        m.rel("stage", stage=101 + 10 * j, gear_1=pg, gear_2=ring)
        if variant == "compound_planetary_set":
            m.comp(102 + 10 * j, "cylindrical_stage", f"Planet-second ring {j + 1}", center_distance=("mm", num(-a)))
            m.rel("assembly", assembly=9, part=102 + 10 * j)
            m.rel("stage", stage=102 + 10 * j, gear_1=pg, gear_2=45)
        if held_carrier:
            b = bearing(m, 80 + j, f"Planet bearing {j + 1}", "", 12.5, "no_direction",
                        kind="concept_bearing", bearing_type=("none", {"enum": "radial_grooved_ball_bearing"}),
                        inner_diameter=("mm", num(20)), outer_diameter=("mm", num(32)))
            m.rel("side", assembly=b, inner_part=pin, outer_part=ps)
        else:
            for k, u in enumerate((6.5, 18.5)):
                b = bearing(m, 80 + 2 * j + k, f"Planet bearing {j + 1}{'ab'[k]}", "", u, "no_direction",
                            bearing_type=("none", {"enum": "radial_needle_roller_bearing"}),
                            inner_diameter=("mm", num(20)), outer_diameter=("mm", num(26)))
                m.rel("side", assembly=b, inner_part=pin, outer_part=ps)
    if held_carrier:
        return m
    # The parallel stage: its pinion on the carrier's far cheek, its wheel on the output shaft.
    gear(m, 91, "Lay pinion", 20, 3, 30, 40, (140, 0, 0))
    m.rel("assembly", assembly=32, part=91)
    shaft(m, 92, "Output shaft", (100, 0, 120))
    gear(m, 93, "Output wheel", 60, 3, 30, 40, (140, 0, 120))
    m.rel("assembly", assembly=92, part=93)
    m.comp(94, "cylindrical_stage", "Parallel stage", center_distance=("mm", num(120)),
           common_face_width=("mm", num(30)), rotating_angle_around_neg_u_axis=("deg", num(0)))
    m.rel("stage", stage=94, gear_1=91, gear_2=93)
    output_shaft_parts(m, 92, (95, 96, 97), "6210", (0, 80), "Output bearing")
    return m


def main():
    written = []
    for variant, folder in [
        ("planetary_and_parallel", "constructs"),
        ("carrier_held", "constructs"),
        ("compound_planetary_set", "err"),
        ("helical_planetary", "constructs"),
        ("floating_sun", "constructs"),
    ]:
        m = unit(variant)
        for ext, text in (("rexs", m.xml()), ("rexsj", m.json())):
            path = ROOT / "tests" / "rexs" / folder / f"{variant}.{ext}"
            path.write_text(text, encoding="utf-8")
            written.append(str(path.relative_to(ROOT)))
    print("\n".join(written), file=sys.stderr)


if __name__ == "__main__":
    main()
