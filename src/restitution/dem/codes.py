"""DEM codes' contact options <-> the model (alpha, gamma, D1, D2, end rule), for two particles: one
import for every engine's dictionary.

Head-on, the overlap delta of two spheres obeys m delta'' + F_el + eta delta' = 0 with the effective
mass m = m1 m2 / (m1 + m2) and radius R = R1 R2 / (R1 + R2); dividing by m gives the model.

Each engine's table lives with the engine, in restitution.dem.engines: LAMMPS ``pair_style
granular`` (engines.lammps.contact), LIGGGHTS ``model hertz`` and ``model hooke``
(engines.liggghts.contact), Yade's ViscElMat and Hertz-Mindlin (engines.yade.contact) and
MercuryDPM's LinearViscoelastic species (engines.mercurydpm.contact); the formulas several of them
share (a typed e, beta(e), E*) in restitution.dem.typed_e, the particles in restitution.dem.pair.
"""

from __future__ import annotations

from .engines.lammps.contact import (DAMPING_MODELS, E_DAMPINGS, LAMMPS_CHECKED, LAMMPS_GRAN_STYLES, NORMAL_MODELS,
                                     TSUJI_POLY, TSUJI_SQRT2_SINCE, TSUJI_VERSION_NOTE, base_eta_n0, lammps_contact,
                                     lammps_eta_n0, lammps_gran_contact, lammps_pair_coeff, restitution_b, tsuji_a)
from .engines.liggghts.contact import (LIGGGHTS_E, LIGGGHTS_MODEL_TYPES, LIGGGHTS_MODELS, LIGGGHTS_MODULUS,
                                       LIGGGHTS_NU, liggghts_accepts_e, liggghts_contact, liggghts_e)
from .engines.mercurydpm.contact import mercury_linear_contact
from .engines.yade.contact import (THORNTON_H, thornton_betan, yade_mindlin_contact, yade_mindlin_en,
                                   yade_viscel_contact, yade_viscel_setting)
from .pair import WALL_SIZE, Pair

__all__ = ["Pair", "WALL_SIZE", "tsuji_a", "lammps_contact", "lammps_pair_coeff", "liggghts_contact", "liggghts_e",
           "mercury_linear_contact", "yade_viscel_contact", "yade_viscel_setting", "yade_mindlin_contact",
           "yade_mindlin_en", "thornton_betan", "NORMAL_MODELS", "DAMPING_MODELS", "E_DAMPINGS", "restitution_b",
           "base_eta_n0", "TSUJI_VERSION_NOTE", "LAMMPS_CHECKED", "TSUJI_SQRT2_SINCE", "LAMMPS_GRAN_STYLES", "lammps_gran_contact",
           "LIGGGHTS_MODELS", "LIGGGHTS_E", "LIGGGHTS_NU", "LIGGGHTS_MODULUS", "LIGGGHTS_MODEL_TYPES", "liggghts_accepts_e",
           "lammps_eta_n0", "TSUJI_POLY", "THORNTON_H"]
