"""YAML read strictly: a key given twice in one mapping is an error, not "the last one wins".

PyYAML keeps the last of two equal keys without a word, so a scene file or a configuration that
sets ``tolerance`` twice, or a material's ``E`` twice, would run with a value its author may not
have meant. YAML 1.2 requires keys to be unique; both the pipeline's ``config.yaml`` and the scene
files (:mod:`restitution.dem.scene_file`) are read with :class:`UniqueKeyLoader`.
"""

from __future__ import annotations

import yaml
from yaml.constructor import ConstructorError

__all__ = ["UniqueKeyLoader"]


class UniqueKeyLoader(yaml.SafeLoader):
    """PyYAML's safe loader, refusing a key given twice in one mapping.

    The refusal is a :class:`yaml.constructor.ConstructorError` whose ``problem_mark`` is the second
    key's place, so a caller that reports YAML errors with their line reports this one the same way.

    Examples
    --------
    >>> import yaml
    >>> yaml.load("a: 1\\nb: 2\\n", Loader=UniqueKeyLoader)
    {'a': 1, 'b': 2}
    >>> try:
    ...     yaml.load("a: 1\\na: 2\\n", Loader=UniqueKeyLoader)
    ... except yaml.YAMLError as err:
    ...     print(err.problem, "at line", err.problem_mark.line + 1)
    a = given twice in one mapping (also on line 1): each key at most once at line 2
    """

    def construct_mapping(self, node, deep=False):
        if isinstance(node, yaml.MappingNode):
            seen = {}
            for key_node, _ in node.value:
                key = self.construct_object(key_node, deep=True)
                try:
                    first = seen.get(key)
                except TypeError:           # an unhashable key: PyYAML's own error follows
                    continue
                if first is not None:
                    raise ConstructorError(
                        None, None,
                        f"{key} = given twice in one mapping (also on line {first + 1}): each key at most once",
                        key_node.start_mark)
                seen[key] = key_node.start_mark.line
        return super().construct_mapping(node, deep)
