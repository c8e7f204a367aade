"""A scene given as a dict, written as the TOML text the scene parser reads (quadmc.run).

tomllib only reads TOML, and the scene's shapes are few, so this small emitter writes them rather
than depend on a TOML writer package: top-level keys, tables ([budget], [output]), arrays of tables
([[integrand]], [[method]]), and as values strings, ints, floats, bools, arrays and inline tables
(N = {from = 64, to = 4096, factor = 4}, warp = {name = "power"}). to_toml(d) read back by
tomllib.loads is d again (tests/python/test_run.py).
"""
import json
import math
import re

_BARE_KEY = re.compile(r"^[A-Za-z0-9_-]+$")


def _key(key):
    if not isinstance(key, str):
        raise ValueError(f"invalid scene key {key!r}: expected a string")
    return key if _BARE_KEY.match(key) else json.dumps(key, ensure_ascii=False)


def _value(value, where):
    # bool before int: True is an int in Python, a different type in TOML.
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        if math.isnan(value):
            return "nan"
        if math.isinf(value):
            return "inf" if value > 0 else "-inf"
        return repr(value)  # the shortest text that reads back to the same double
    if isinstance(value, str):
        # A JSON string is a TOML basic string: the same escapes (\" \\ \n \uXXXX).
        return json.dumps(value, ensure_ascii=False)
    if isinstance(value, dict):
        items = ", ".join(f"{_key(k)} = {_value(v, f'{where}.{k}')}" for k, v in value.items())
        return "{" + items + "}"
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_value(v, f"{where}[{i}]") for i, v in enumerate(value)) + "]"
    raise ValueError(f"invalid scene value {where} = {value!r}: expected a string, number, bool, "
                     "list or dict")


def _is_table_array(value):
    return isinstance(value, (list, tuple)) and len(value) > 0 and all(
        isinstance(v, dict) for v in value)


def _pairs(table, where):
    return [f"{_key(k)} = {_value(v, f'{where}{k}')}" for k, v in table.items()]


def to_toml(scene):
    """The TOML text of a scene dict: plain keys first, then [tables], then [[arrays of tables]]."""
    if not isinstance(scene, dict):
        raise ValueError(f"invalid scene {scene!r}: expected a dict")
    plain = {k: v for k, v in scene.items() if not isinstance(v, dict) and not _is_table_array(v)}
    lines = _pairs(plain, "")
    for key, value in scene.items():
        if isinstance(value, dict):
            lines += ["", f"[{_key(key)}]"] + _pairs(value, f"{key}.")
    for key, value in scene.items():
        if _is_table_array(value):
            for i, table in enumerate(value):
                lines += ["", f"[[{_key(key)}]]"] + _pairs(table, f"{key}[{i}].")
    return "\n".join(lines) + "\n"
