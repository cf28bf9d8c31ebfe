"""YAML read strictly: what two readers of one file could take differently is refused, in one line.

Every YAML input of the project (the scene files of :mod:`restitution.dem.scene.file`, the
pipeline's ``config.yaml``) is read with :class:`StrictLoader`, PyYAML's safe loader with these
refusals:

- a key given twice in one mapping: PyYAML keeps the last without a word, so a ``tolerance`` or a
  material's ``E`` set twice would run with a value its author may not have meant;
- a value YAML 1.1 and YAML 1.2 read differently. PyYAML, and Snakemake which loads
  ``config.yaml`` with it, follow YAML 1.1: ``02500`` is octal 1344 there and 2500 in YAML 1.2,
  ``41:40`` is sexagesimal 2500 there and text in YAML 1.2, ``2_500`` is 2500 there and text in
  YAML 1.2, ``no``, ``yes``, ``on``, ``off`` are booleans there and text in YAML 1.2, a date is a
  date there and text in YAML 1.2, ``0o17`` is text there and 15 in YAML 1.2. ``0x9C4`` and
  ``0b101`` are numbers to some readers and text to others (YAML 1.2's JSON schema). So a number
  is written in plain decimal (``2500``, ``2.5e3``), a boolean as ``true`` or ``false``, and text
  that looks like either is quoted; then every reader takes the same value. The one reading added is YAML 1.2's for ``6.3e10`` or
  ``1e-3`` (text to YAML 1.1), which every modeller means as a number;
- a number beyond the range of a double (a 400-digit ``tolerance``: it would become inf, or an
  integer Python keeps but the physics cannot), or a nonzero one below it (it would become 0);
- nesting deeper than :data:`MAX_DEPTH` levels (Python's recursion limit would end the reading in
  a RecursionError; no input of the project nests beyond 6).

Refusals are :class:`Refused`, a :class:`yaml.constructor.ConstructorError` whose ``problem``
names the field and the value and whose ``problem_mark`` is the value's place.
"""

from __future__ import annotations

import re
import sys

import yaml
from yaml.constructor import ConstructorError
from yaml.nodes import ScalarNode

__all__ = ["StrictLoader", "Refused", "MAX_DEPTH"]

#: Deepest nesting of mappings and sequences read
MAX_DEPTH = 100

_INT = re.compile(r"[-+]?(?:0|[1-9][0-9]*)")
_OCTAL_1_2 = re.compile(r"0o[0-7]+")
_FLOAT = re.compile(r"[-+]?(?:\.[0-9]+|[0-9]+(?:\.[0-9]*)?)(?:[eE][-+]?[0-9]+)?|[-+]?\.(?:inf|Inf|INF)|\.(?:nan|NaN|NAN)")
_BOOL = {"true": True, "True": True, "TRUE": True, "false": False, "False": False, "FALSE": False}
_SPELLING = "write numbers in plain decimal (2500, 2.5e3), booleans as true or false, and quote text"


class Refused(ConstructorError):
    """A value, key or structure :class:`StrictLoader` does not take (see the module docstring)."""

    def __init__(self, problem: str, mark):
        super().__init__(None, None, problem, mark)


def _show(text: str) -> str:
    return text if len(text) <= 24 else f"{text[:12]}...{text[-4:]} ({len(text)} characters)"


class StrictLoader(yaml.SafeLoader):
    """PyYAML's safe loader, refusing what two readers could take differently (module docstring).

    Examples
    --------
    >>> import yaml
    >>> yaml.load("a: 1\\nb: 2.5e3\\nc: true\\nd: '02500'\\n", Loader=StrictLoader)
    {'a': 1, 'b': 2500.0, 'c': True, 'd': '02500'}
    >>> for text in ("a: 1\\na: 2\\n", "size: 02500\\n", "limitForce: on\\n", "tolerance: 1e400\\n"):
    ...     try:
    ...         yaml.load(text, Loader=StrictLoader)
    ...     except yaml.YAMLError as err:
    ...         print(err.problem, "at line", err.problem_mark.line + 1)
    a = given twice in one mapping (also on line 1): each key at most once at line 2
    size = 02500: YAML readers differ on it (YAML 1.1, PyYAML's and Snakemake's, reads 1344); write numbers in plain decimal (2500, 2.5e3), booleans as true or false, and quote text at line 1
    limitForce = on: YAML readers differ on it (YAML 1.1, PyYAML's and Snakemake's, reads True); write numbers in plain decimal (2500, 2.5e3), booleans as true or false, and quote text at line 1
    tolerance = 1e400: beyond the range of a double (magnitude at most 1.8e+308) at line 1
    """

    _depth = 0

    def compose_node(self, parent, index):
        if self._depth >= MAX_DEPTH:
            raise Refused(f"nested deeper than {MAX_DEPTH} levels: not an input of this project",
                          self.peek_event().start_mark)
        self._depth += 1
        try:
            return super().compose_node(parent, index)
        finally:
            self._depth -= 1

    def construct_mapping(self, node, deep=False):
        if isinstance(node, yaml.MappingNode):
            seen = {}
            for key_node, value_node in node.value:
                key = self.construct_object(key_node, deep=True)
                if isinstance(value_node, ScalarNode):
                    try:    # constructed here to name the key; the mapping reuses the value
                        self.construct_object(value_node)
                    except Refused as err:
                        raise Refused(f"{key} = {err.problem}", err.problem_mark) from None
                try:
                    first = seen.get(key)
                except TypeError:           # an unhashable key: PyYAML's own error follows
                    continue
                if first is not None:
                    raise Refused(f"{key} = given twice in one mapping (also on line {first + 1}): "
                                  "each key at most once", key_node.start_mark)
                seen[key] = key_node.start_mark.line
        return super().construct_mapping(node, deep)

    def _differ(self, node, yaml_1_1=None):
        text = self.construct_scalar(node)
        value = text if yaml_1_1 is None else yaml_1_1(self, node)
        reading = (repr(value) if isinstance(value, (bool, int, float)) else f"the text {text!r}"
                   if isinstance(value, str) else f"a {type(value).__name__} ({value})")
        return Refused(f"{_show(text)}: YAML readers differ on it (YAML 1.1, PyYAML's and Snakemake's, reads "
                       f"{_show(reading)}); {_SPELLING}", node.start_mark)

    def construct_strict_int(self, node):
        text = self.construct_scalar(node)
        if _OCTAL_1_2.fullmatch(text):     # YAML 1.2's octal, text to YAML 1.1
            raise self._differ(node)
        if not _INT.fullmatch(text):
            raise self._differ(node, yaml.SafeLoader.construct_yaml_int)
        # more digits than any double has, or beyond its range: refused before int() reads them all
        if len(text.lstrip("+-")) > 309 or abs(int(text)) > sys.float_info.max:
            raise Refused(f"{_show(text)}: beyond the range of a double (magnitude at most "
                          f"{sys.float_info.max:.2g})", node.start_mark)
        return int(text)

    def construct_strict_float(self, node):
        text = self.construct_scalar(node)
        if not _FLOAT.fullmatch(text):
            raise self._differ(node, yaml.SafeLoader.construct_yaml_float)
        if "n" in text.lower():   # .inf, .nan: their own checks (a field that must be finite says so)
            return yaml.SafeLoader.construct_yaml_float(self, node)
        value = float(text)
        if value in (float("inf"), float("-inf")):
            raise Refused(f"{_show(text)}: beyond the range of a double (magnitude at most "
                          f"{sys.float_info.max:.2g})", node.start_mark)
        if value == 0 and re.search(r"[1-9]", text.lower().split("e")[0]):
            raise Refused(f"{_show(text)}: below the smallest double ({5e-324:.2g}): it would read as 0",
                          node.start_mark)
        return value

    def construct_strict_bool(self, node):
        text = self.construct_scalar(node)
        if text not in _BOOL:
            raise self._differ(node, yaml.SafeLoader.construct_yaml_bool)
        return _BOOL[text]

    def construct_strict_timestamp(self, node):
        raise self._differ(node, yaml.SafeLoader.construct_yaml_timestamp)


# YAML 1.2 reads 6.3e10 and 1e-3 as numbers; YAML 1.1 wants a dot and a signed exponent
StrictLoader.add_implicit_resolver(
    "tag:yaml.org,2002:float", re.compile(r"^[-+]?(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)[eE][-+]?[0-9]+$"),
    list("-+0123456789."))
StrictLoader.add_implicit_resolver("tag:yaml.org,2002:int", re.compile(f"^{_OCTAL_1_2.pattern}$"), ["0"])
StrictLoader.add_constructor("tag:yaml.org,2002:int", StrictLoader.construct_strict_int)
StrictLoader.add_constructor("tag:yaml.org,2002:float", StrictLoader.construct_strict_float)
StrictLoader.add_constructor("tag:yaml.org,2002:bool", StrictLoader.construct_strict_bool)
StrictLoader.add_constructor("tag:yaml.org,2002:timestamp", StrictLoader.construct_strict_timestamp)
