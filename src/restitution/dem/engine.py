"""The contract every DEM engine meets, so that scenes, the typed-e table, designers and the command
line look an engine up (restitution.dem.engines.ENGINES) instead of naming it.

An engine is one object: its contact law and its parameters both ways (:meth:`Engine.contact`,
:meth:`Engine.setting`), its designer (:meth:`Engine.design`), its runner (the module that runs
the real engine, or None where it is not installed), the settings whose damping is a typed e
(``typed_e``), the hook of its deck dialect (``deck``, from ``deck_module``), and, for an engine a
scene file may name (``scene_options`` not None), the scene's hooks: end rule, candidate models,
each contact's setting and input lines. An engine run as a child process describes how
(:class:`EngineProcess`), and its runner's eps then follows the same steps as every other's.
"""

from __future__ import annotations

import importlib
import shutil
from collections.abc import Callable
from dataclasses import dataclass

from ..core.errors import ParameterError

__all__ = ["Engine", "EngineProcess", "rebound_eps"]


class Engine:
    """One DEM engine, as the rest of the DEM layer sees it.

    A subclass sets the attributes and overrides the methods its engine supports; a method it
    leaves raises ParameterError naming the engine.

    Attributes
    ----------
    name : str
        The registry key, and the ``code`` a scene file names.
    label : str
        The engine as messages name it (``"LAMMPS"``).
    typed_e : dict
        {row label: function of a typed e -> Contact} for each setting whose damping is set from a
        restitution coefficient e.
    version : str
        The engine release the ``typed_e`` rows are confirmed in (by running them in it).
    typed_e_steps : int
        Steps per contact of the coarsest of the three runs (then twice and four times as many)
        that confirm the ``typed_e`` rows in the engine (tests/library/test_dem_typed_e.py).
    install_hint : str
        What installs the real engine (the reason a test that needs it is skipped with).
    deck_module : str or None
        The dotted name of the engine's deck dialect module, where it has one (:attr:`deck`
        imports it when first asked, so that the registry never imports the deck reader).
    runner_module : str or None
        The dotted name of the module that runs the real engine (its ``available()`` says whether
        the engine is installed).
    materials_module : str or None
        The dotted name of the module that audits the engine's material file, where its contacts
        are set in one (not a deck): its ``is_materials_file(text)`` claims a file ``restitution
        deck`` is given, its ``audit_materials(text, speeds, radius, read_file)`` answers it.
    sample_setting : tuple
        (a setting of :meth:`Engine.contact`, the keywords :meth:`Engine.setting` is given to
        find it again): the registry's tests invert every engine's law through it, so that a new
        engine brings its own case instead of editing theirs.
    scene_input_file : str
        The file ``restitution scene --out`` writes the scene's input lines to.
    scene_option_schema : dict
        {option: its JSON schema} (a description, an ``enum`` or a ``type``, and a ``default`` unless
        the option is required); empty where scenes cannot name the engine. The scene file's schema
        takes each scene engine's options from here, and a missing required option is answered
        with its ``enum``.

    Examples
    --------
    >>> from restitution.dem.engines import ENGINES
    >>> ENGINES["lammps"].label, ENGINES["lammps"].end_rule({"limit_damping": True})
    ('LAMMPS', 'force')
    """

    name: str = ""
    label: str = ""
    typed_e: dict = {}
    version: str = ""
    typed_e_steps: int = 0
    install_hint: str = ""
    deck_module: str | None = None
    runner_module: str | None = None
    materials_module: str | None = None
    sample_setting: tuple = ()
    scene_option_schema: dict = {}
    scene_input_file: str = "input.lammps"

    @property
    def scene_options(self) -> dict | None:
        """The scene options and their defaults (None: required), read from ``scene_option_schema``;
        None where scenes cannot name the engine."""
        if not self.scene_option_schema:
            return None
        return {name: rule.get("default") for name, rule in self.scene_option_schema.items()}

    def _missing(self, what: str):
        raise ParameterError("code", self.name, f"{self.label} has no {what} in this library")

    # the contact law, both ways
    def contact(self, pair, **setting):
        """The model (a Contact) this setting of the engine gives for ``pair``."""
        self._missing("contact law")

    def setting(self, pair, contact, **given) -> dict:
        """The setting, with ``given`` fixed, that gives ``contact`` for ``pair``."""
        self._missing("inverse of its contact law")

    def design(self, pair, **target) -> dict:
        """The setting that reaches an eps (``target``: eps, g and the fixed keywords)."""
        self._missing("designer")

    def typed_e_case(self, row: str, e: float, pair, material: dict) -> tuple:
        """(the contact the ``typed_e`` row ``row`` gives at a typed e for ``pair``, the engine's
        setting as its runner's ``eps_runs(pair, [(setting, g, dt, t_run), ...])`` takes it);
        ``material``: E and nu where the row's stiffness reads them."""
        self._missing("typed-e runs")

    @property
    def deck(self):
        """The engine's deck dialect module, or None where the library reads no deck of it."""
        return None if self.deck_module is None else importlib.import_module(self.deck_module)

    @property
    def materials(self):
        """The engine's material-file module, or None where its contacts are not set in one."""
        return None if self.materials_module is None else importlib.import_module(self.materials_module)

    @property
    def runner(self):
        """The module that runs the real engine, or None where it is not installed: its
        ``eps_runs(pair, cases)`` gives the engine's eps of each case (setting, g, dt, t_run), in
        order, the setting as :meth:`Engine.typed_e_case` gives it."""
        if self.runner_module is None:
            return None
        module = importlib.import_module(self.runner_module)
        return module if module.available() else None

    # scenes
    def end_rule(self, options: dict) -> str:
        """The end-of-contact rule the scene options give ("force" or "overlap")."""
        self._missing("scenes")

    def material_keys(self, options: dict) -> tuple:
        """(the keys each material must give, the name of what reads them in messages)."""
        self._missing("scenes")

    def check_material(self, name: str, material: dict) -> None:
        """Refuse (ParameterError) a material the engine stops on though the schema allows it."""

    def models(self, options: dict) -> list:
        """The candidate contact models (model_choice.ContactModel), cheapest first."""
        self._missing("scenes")

    def scene_setting(self, scene, contact, fit) -> dict:
        """The setting of one scene contact (scene.contacts.SceneContact) for a fitted model, as
        its input line prints it; ParameterError where the engine cannot express it."""
        self._missing("scenes")

    def wall_types(self, scene) -> dict:
        """{wall: atom type} where the engine gives walls atom types of their own, else {}."""
        return {}

    def contact_lines(self, scene, contact, setting: dict) -> list:
        """The input lines of one scene contact."""
        self._missing("scenes")

    def input_lines(self, scene, rows: list) -> list:
        """The whole scene's input lines from its answered contacts (rows)."""
        self._missing("scenes")

    def notes(self, settings) -> list:
        """What to say beside an answer made of these settings (one line each, for stderr)."""
        return []


def rebound_eps(ends, speeds, label: str) -> list[float]:
    """eps of each head-on run from the state it ended in: eps = -(v1 - v2) / g, the runners'
    common last step (the bodies approach at v1 - v2 = g > 0 and rebound at -eps g).

    Parameters
    ----------
    ends : iterable of (float, float)
        (relative normal velocity v1 - v2, distance between the surfaces) at the end of each run.
    speeds : iterable of float
        Each run's approach speed g, in the same order.
    label : str
        The engine, as the refusal names it.

    Returns
    -------
    list of float
        eps of each run, in order.

    Raises
    ------
    ArithmeticError
        Where a run ended with the surfaces still touching (its velocity is not yet the rebound's).
    ValueError
        Where ``ends`` and ``speeds`` differ in length (a run whose state the engine did not report).

    Examples
    --------
    >>> rebound_eps([(-0.5, 1e-4), (-1.5, 2e-5)], [1.0, 2.0], "Yade")
    [0.5, 0.75]
    >>> rebound_eps([(-0.5, 0.0)], [1.0], "Yade")
    Traceback (most recent call last):
    ...
    ArithmeticError: the bodies had not separated at the end of the Yade run
    """
    eps = []
    for (rel, gap), g in zip(ends, speeds, strict=True):
        if gap <= 0.0:
            raise ArithmeticError(f"the bodies had not separated at the end of the {label} run")
        eps.append(-rel / g)
    return eps


@dataclass(frozen=True)
class EngineProcess:
    """A real engine that runs head-on collisions as a child process, every case of a call in one
    process (LIGGGHTS, Yade and Kratos each take a second or more to start): the engine reads how
    each run ended (``ends``), and :meth:`eps_runs` turns that into eps the same way for all.

    Parameters
    ----------
    label : str
        The engine, as messages name it.
    case : str
        The engine's case tuple in words: what :meth:`eps_runs` takes per run.
    speed_at : int
        Where a case holds its approach speed g.
    ends : callable
        ``ends(pair, cases, timeout)`` -> (relative normal velocity v1 - v2, distance between the
        surfaces) at the end of each case, all from one process of the engine.
    timeout : float, optional
        Seconds the engine may take where a call gives none.
    program : str, optional
        The program the engine is started as, where it is one on PATH (:meth:`available`).

    Examples
    --------
    A stand-in engine whose runs all rebound at half their approach speed:

    >>> toy = EngineProcess("Toy", "(setting, g, dt, t_run)", 1,
    ...                     lambda pair, cases, timeout: [(-0.5 * g, 1e-4) for _, g, _, _ in cases])
    >>> toy.eps_runs(None, [("lines", 1.0, 1e-7, 1e-3), ("lines", 2.0, 1e-7, 1e-3)])
    [0.5, 0.5]
    """

    label: str
    case: str
    speed_at: int
    ends: Callable
    timeout: float = 600.0
    program: str | None = None

    def available(self) -> bool:
        """Whether the engine's program is on PATH (the runner form's ``available()``, where the
        engine is started as a program).

        Returns
        -------
        bool
            True where the engine can be run; the tests that run it are skipped otherwise.

        Examples
        --------
        >>> EngineProcess("Toy", "(setting, g, dt, t_run)", 1, None, program="no-such-engine-here").available()
        False
        """
        return self.program is not None and shutil.which(self.program) is not None

    def eps_runs(self, pair, cases: list, timeout: float | None = None) -> list[float]:
        """eps of each case, all in one process of the engine (each engine's runner form; the
        engine's module names it ``<engine>_eps_runs`` too).

        Parameters
        ----------
        pair : Pair
            The two spheres (a ``Pair.wall`` for a sphere on a wall, where the engine runs one).
        cases : list of tuple
            One case per run, in the engine's form (:attr:`case`), its approach speed g at
            :attr:`speed_at`.
        timeout : float, optional
            Seconds the engine may take (:attr:`timeout` where not given).

        Returns
        -------
        list of float
            The engine's eps of each run, in order.

        Raises
        ------
        RuntimeError
            Where the engine stops.
        ArithmeticError
            Where a run ended with the surfaces still touching (:func:`rebound_eps`).

        Examples
        --------
        A stand-in engine whose run ends with the bodies still pressed together is refused:

        >>> stuck = EngineProcess("Toy", "(setting, g, dt, t_run)", 1, lambda pair, cases, timeout: [(0.2, 0.0)])
        >>> stuck.eps_runs(None, [("lines", 1.0, 1e-7, 1e-3)])
        Traceback (most recent call last):
        ...
        ArithmeticError: the bodies had not separated at the end of the Toy run
        """
        ends = self.ends(pair, cases, self.timeout if timeout is None else timeout)
        return rebound_eps(ends, [case[self.speed_at] for case in cases], self.label)
