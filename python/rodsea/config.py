"""Configs from a TOML file or a dict, validated and resolved by the same code as the CLI."""
import math
import os

from . import _rodsea


def _literal(value, key):
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        if not math.isfinite(value):
            raise _rodsea.InvalidParameter(f"invalid {key} = {value}: allowed a finite number")
        return repr(value)
    if isinstance(value, str):
        return '"' + value.replace("\\", "\\\\").replace('"', '\\"') + '"'
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_literal(v, key) for v in value) + "]"
    raise _rodsea.InvalidParameter(
        f"invalid {key} = {value!r}: allowed a number, a string, a boolean or a list of them")


def to_toml(config):
    """A dict shaped like the TOML file ({"box": {"side": 30.0}, "species": [{...}, ...]}) as TOML
    text. Nested tables ("collisions": {"pair": [...]}) become [collisions.pair] tables."""
    lines = []

    def table(path, values):
        scalars = {k: v for k, v in values.items() if not isinstance(v, dict)
                   and not (isinstance(v, list) and v and all(isinstance(x, dict) for x in v))}
        lines.append(f"[{path}]")
        for k, v in scalars.items():
            lines.append(f"{k} = {_literal(v, path + '.' + k)}")
        for k, v in values.items():
            if isinstance(v, dict):
                table(f"{path}.{k}", v)
            elif isinstance(v, list) and v and all(isinstance(x, dict) for x in v):
                for element in v:
                    array_table(f"{path}.{k}", element)

    def array_table(path, values):
        lines.append(f"[[{path}]]")
        for k, v in values.items():
            lines.append(f"{k} = {_literal(v, path + '.' + k)}")

    if not isinstance(config, dict):
        raise _rodsea.InvalidParameter(
            f"invalid config = {type(config).__name__}: allowed a path or a dict")
    for name, value in config.items():
        if isinstance(value, dict):
            table(name, value)
        elif isinstance(value, list) and all(isinstance(x, dict) for x in value):
            for element in value:
                array_table(name, element)
        else:
            raise _rodsea.InvalidParameter(
                f"invalid {name} = {value!r}: allowed a table (a dict) or an array of tables")
    return "\n".join(lines) + "\n"


def load_config(source, name=None):
    """A validated, resolved rodsea.Config from a TOML file's path or a dict of its tables.
    Raises rodsea.InvalidParameter naming the key, as `rodsea run` would."""
    if isinstance(source, (str, os.PathLike)):
        return _rodsea._load_config_file(os.fspath(source))
    return _rodsea._load_config_text(to_toml(source), name or "<dict>")
