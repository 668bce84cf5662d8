"""A dict of an aircraft file's keys as the text of that file (TOML), for the loader that reads
files: the same checks and messages whatever form the aircraft is given in."""

from __future__ import annotations

import json
import math
from typing import Any, List, Mapping


def _value(v: Any, key: str) -> str:
    """One TOML value; floats in shortest round-trip form, so the loader reads them bit for bit."""
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        if math.isnan(v):
            return "nan"
        if math.isinf(v):
            return "inf" if v > 0 else "-inf"
        return repr(v)
    if isinstance(v, str):
        return json.dumps(v)
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(_value(x, key) for x in v) + "]"
    raise TypeError(f"{key}: {v!r} is not a TOML value (number, string, boolean or list)")


def toml_text(d: Mapping[str, Any]) -> str:
    """The TOML text of ``d``: its plain keys first, then one table per dict value."""
    lines: List[str] = []
    tables = []
    for k, v in d.items():
        if isinstance(v, Mapping):
            tables.append((k, v))
        else:
            lines.append(f"{json.dumps(str(k))} = {_value(v, k)}")
    for name, table in tables:
        lines.append(f"\n[{json.dumps(str(name))}]")
        for k, v in table.items():
            lines.append(f"{json.dumps(str(k))} = {_value(v, f'{name}.{k}')}")
    return "\n".join(lines) + "\n"
