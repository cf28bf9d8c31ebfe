"""The contacts a scene can have: every pair of atom types, and every atom type on every wall,
each with its two particles (a Pair)."""

from __future__ import annotations

from dataclasses import dataclass

from ..pair import Pair
from .file import AtomType, Scene

__all__ = ["SceneContact", "scene_contacts"]


@dataclass
class SceneContact:
    """One contact of a scene: atom type ``a`` on atom type ``b``, or on the wall ``wall``."""

    a: AtomType
    b: AtomType | None       # None: a wall
    wall: str | None
    pair: Pair

    @property
    def materials(self) -> tuple:
        return (self.a.material, self.b.material if self.b is not None else self.wall)


def scene_contacts(scene: Scene) -> list[SceneContact]:
    """Every contact of ``scene``: type pairs first (in file order), then types on walls."""
    dens = {m: float(v["density"]) for m, v in scene.materials.items()}
    out = []
    for i, a in enumerate(scene.types):
        for b in scene.types[i:]:
            out.append(SceneContact(a, b, None, Pair.spheres(a.radius, b.radius, dens[a.material], dens[b.material])))
    for a in scene.types:
        for w in scene.walls:
            out.append(SceneContact(a, None, w, Pair.wall(a.radius, dens[a.material])))
    return out
