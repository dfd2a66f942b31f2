"""Configs from a TOML file or a dict, validated and resolved by the same code as the CLI."""
import math
import numbers
import os
import re

import numpy

from . import _rodsea


# Every key of a config is a bare TOML key; anything else pasted into the text could close the
# table and open another.
_BARE_KEY = re.compile(r"[A-Za-z0-9_-]+")


def _key(name, path):
    if not isinstance(name, str) or not _BARE_KEY.fullmatch(name):
        where = f" in {path}" if path else ""
        raise _rodsea.InvalidParameter(
            f"invalid key {name!r}{where}: allowed a config key (letters, digits, _ and -; "
            "docs/config.md)")
    return name


def _literal(value, key):
    # numpy's scalars (an element of an array) count as the numbers they are.
    if isinstance(value, (bool, numpy.bool_)):
        return "true" if value else "false"
    if isinstance(value, numbers.Integral):
        return str(int(value))
    if isinstance(value, numbers.Real):
        value = float(value)
        if not math.isfinite(value):
            raise _rodsea.InvalidParameter(f"invalid {key} = {value}: allowed a finite number")
        return repr(value)
    if isinstance(value, str):
        # A TOML basic string: quotes, backslashes and control characters escaped (a newline
        # pasted as it is would end the line and read as a syntax error).
        return '"' + "".join(
            "\\" + c if c in '"\\' else f"\\u{ord(c):04x}" if ord(c) < 0x20 or ord(c) == 0x7F
            else c for c in value) + '"'
    if isinstance(value, (list, tuple, numpy.ndarray)):
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
            lines.append(f"{_key(k, path)} = {_literal(v, path + '.' + k)}")
        for k, v in values.items():
            _key(k, path)
            if isinstance(v, dict):
                table(f"{path}.{k}", v)
            elif isinstance(v, list) and v and all(isinstance(x, dict) for x in v):
                for element in v:
                    array_table(f"{path}.{k}", element)

    def array_table(path, values):
        if not isinstance(values, dict):
            raise _rodsea.InvalidParameter(
                f"invalid {path} = {values!r}: allowed a table (a dict)")
        lines.append(f"[[{path}]]")
        for k, v in values.items():
            lines.append(f"{_key(k, path)} = {_literal(v, path + '.' + k)}")

    if not isinstance(config, dict):
        raise _rodsea.InvalidParameter(
            f"invalid config = {type(config).__name__}: allowed a path or a dict")
    for name, value in config.items():
        _key(name, "")
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
