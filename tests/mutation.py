"""One edit of a nested config or scene dict, as the bad-input tests make them."""

from __future__ import annotations


def set_at(path, value):
    """A function that sets ``value`` at ``path`` (keys and list indices) of the dict it is given."""
    def change(d):
        node = d
        for key in path[:-1]:
            node = node[key]
        node[path[-1]] = value
    return change
