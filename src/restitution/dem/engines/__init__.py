"""The registry of DEM engines: each engine is one object (restitution.dem.engine.Engine) under its
name; scenes, the typed-e table, designers and the command line look engines up here."""

from __future__ import annotations

from .kratos.engine import KRATOS
from .lammps.engine import LAMMPS
from .liggghts.engine import LIGGGHTS
from .mercurydpm.engine import MERCURYDPM
from .yade.engine import YADE

__all__ = ["ENGINES", "scene_engines"]

#: name -> Engine, in the order tables list them
ENGINES = {e.name: e for e in (LAMMPS, LIGGGHTS, YADE, MERCURYDPM, KRATOS)}


def scene_engines() -> list[str]:
    """The names a scene file's ``code`` may take: the engines that write scenes.

    Returns
    -------
    list of str

    Examples
    --------
    >>> "lammps" in scene_engines()
    True
    """
    return [name for name, e in ENGINES.items() if e.scene_options is not None]
