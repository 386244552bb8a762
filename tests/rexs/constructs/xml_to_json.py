#!/usr/bin/env python3
"""Writes a REXS XML model as REXS JSON (the same components, attributes, relations and load
cases; a number as `floating_point`, an array of numbers as `floating_point_array`, true/false as
`boolean`, other text as `string`). Used for the JSON twins of hand-made XML constructs:
python3 tests/rexs/constructs/xml_to_json.py IN.rexs OUT.rexsj"""

import json
import sys
import xml.etree.ElementTree as ET


def value(a):
    array = a.find("array")
    if array is not None:
        cells = [c.text.strip() for c in array.findall("c")]
        if cells and all(c in ("true", "false") for c in cells):
            return {"boolean_array": [c == "true" for c in cells]}
        return {"floating_point_array": [float(c) for c in cells]}
    text = (a.text or "").strip()
    if text in ("true", "false"):
        return {"boolean": text == "true"}
    try:
        return {"floating_point": float(text)}
    except ValueError:
        return {"string": text}


def attributes(c):
    return [dict({"id": a.get("id"), "unit": a.get("unit") or "none"}, **value(a)) for a in c.findall("attribute")]


def main(src, dst):
    root = ET.parse(src).getroot()
    model = {
        "version": root.get("version"),
        "applicationId": root.get("applicationId"),
        "applicationVersion": root.get("applicationVersion"),
        "date": root.get("date"),
        "relations": [
            {
                "id": int(r.get("id")),
                "type": r.get("type"),
                "refs": [{"id": int(x.get("id")), "role": x.get("role"), "hint": x.get("hint")} for x in r.findall("ref")],
            }
            for r in root.find("relations").findall("relation")
        ],
        "components": [
            {"id": int(c.get("id")), "name": c.get("name"), "type": c.get("type"), "attributes": attributes(c)}
            for c in root.find("components").findall("component")
        ],
    }
    spectrum = root.find("load_spectrum")
    if spectrum is not None:
        model["load_spectrum"] = {
            "id": int(spectrum.get("id")),
            "load_cases": [
                {
                    "id": int(case.get("id")),
                    "components": [{"id": int(c.get("id")), "attributes": attributes(c)} for c in case.findall("component")],
                }
                for case in spectrum.findall("load_case")
            ],
        }
    with open(dst, "w", encoding="utf-8") as f:
        json.dump({"model": model}, f, indent=2, ensure_ascii=False)
        f.write("\n")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
