"""The generic reader of LAMMPS-family decks: what each command that runs does to the settings of a
head-on two-sphere contact (:class:`~restitution.dem.dialect.state.Deck`), for every engine alike
(box, atoms, sizes, groups, fixes that pour or insert, data files, labels, runs and their stages).
What a pair style, its coefficients and its walls mean is an engine's: :data:`DIALECTS` gives the
dialect of each engine of the registry that has one (:mod:`restitution.dem.engines.lammps.deck`,
:mod:`restitution.dem.engines.liggghts.deck`), and :data:`PAIR_STYLES` the dialect of each pair
style. Which commands run (if, jump, label, next, quit, include, variable) is the engine's own:
:func:`read_executed` reads the linear stream of commands it executed.
"""

from __future__ import annotations

import copy
import math
import os
import re

from .beside import ADAPT, BESIDE, adapt_parts, adapted_diameter
from .meeting import BROWNIAN, MOVERS, neigh_modify, rigid, special_bonds
from .scratch import GUARDED
from .stream import SEEDED
from .runtime import boundary_faces, constant_in_time
from ..dialect.state import (DEFAULT_SKIN, Deck, DeckError, atom_type, fetch, labelmap, number, number_or_none, place, pour_into,
                             type_pairs, types, unlabeled)
from ..deck_text import ScriptError, if_branches, words
from ..engines import ENGINES
from ..engines.lammps.deck import DEFAULT_DT, own_cutoff

__all__ = ["DIALECTS", "PAIR_STYLES", "MAX_STAGES", "read_executed", "contact_key", "repour", "adapt_poured",
           "by_position"]

#: Engine (a Deck's ``code``) -> its deck dialect: the module that reads its pair style, its
#: coefficients and its walls, as each registered engine's deck hook names it
DIALECTS = {engine.deck.ENGINE: engine.deck for engine in ENGINES.values() if engine.deck_module is not None}
#: Pair style -> the dialect that reads it
PAIR_STYLES = {style: dialect for dialect in DIALECTS.values() for style in dialect.PAIR_STYLES}

#: Commands with no bearing on a head-on two-sphere contact (first word, or "fix STYLE"). Not here,
#: so named when met: mass (per-type masses). The script's control flow (if, jump, label, next,
#: quit, include, variable) is the engine's.
_IRRELEVANT = {"units", "atom_style", "atom_modify", "boundary", "newton", "communicate", "comm_modify",
               "processors", "region", "lattice", "change_box", "neighbor", "neigh_modify", "timestep", "thermo",
               "thermo_style", "thermo_modify", "dump", "dump_modify", "undump", "run", "unfix", "compute",
               "uncompute", "velocity", "delete_atoms", "write_restart", "restart", "log", "print",
               "echo", "label", "shell", "clear", "create_atoms", "displace_atoms",
               "write_data", "write_dump", "reset_timestep", "run_style", "min_style", "minimize", "balance",
               "partition", "suffix", "package", "kspace_style", "special_bonds", "hard_particles",
               "soft_particles", "modify_timing", "compute_modify", "comm_style", "dimension",
               # copies of the atoms there are, sizes, types and groups kept (the engine holds them)
               "replicate",
               # atom IDs given anew, the spheres, their places and velocities kept; a minimizer's
               # settings (field round 46, lists: both "not understood" from the start)
               "reset_atoms", "reset_atom_ids", "min_modify",
               # a bonded interaction's coefficients: where its style has a force, the pairs are named
               # for the style (meeting.excluded)
               "bond_coeff", "angle_coeff", "dihedral_coeff", "improper_coeff"}
#: The styles of bonded interactions, read for whether they have a force (field round 47, Y08)
_BONDED_STYLES = {"bond_style", "angle_style", "dihedral_style", "improper_style"}
_IRRELEVANT_FIXES = {"gravity", "nve/sphere", "nve", "balance", "insert/pack", "deposit",
                     "insert/stream", "insert/rate/region", "particledistribution/discrete", "check/timestep/gran",
                     "enforce2d", "move",
                     "ave/time", "ave/atom", "print", "move/mesh", "halt",
                     # averaging fixes push nothing (field round 16, v01b v03 v04: "may add forces" said)
                     "ave/chunk", "ave/correlate", "ave/correlate/long", "ave/histo", "ave/histo/weight", "vector",
                     "heat/gran", "heat/gran/conduction", "heat/flow", "multisphere", "property/atom",
                     "nve/noforce",
                     # stores values, and the plain integrators an accelerator's suffix names (field
                     # round 46, lists: "may add forces" said of each)
                     "store/state", "nve/sphere/omp", "nve/omp", "nve/sphere/kk", "nve/kk"} \
    | BROWNIAN                       # movers whose pairs meeting.motion names (field round 47, F36)
#: Fixes that push no atom but change what the runs see, each with what it does: named as such, not
#: as a force (field round 15: "may add forces" said of each). Where a run sees fix set or atom/swap,
#: the runs are made for real (:func:`restitution.dem.deck.runtime.resized_by_runs`)
_NO_FORCE = {"set": "sets its atoms' attributes as the runs go (where a run sees it, the audit makes the runs "
                    "and reads the sizes and types they reach)",
             "atom/swap": "swaps its atoms' types as the runs go (where a run sees it, the audit makes the runs "
                          "and reads the types they reach)",
             "evaporate": "deletes atoms as the runs go", "deform": "changes the box as the runs go"}
#: LIGGGHTS move/mesh motions that accelerate a face under a sphere during a contact, so that the
#: eps the engine measures depends on when in the cycle and where on the face a contact falls:
#: an oscillation (LIGGGHTS: 0.543 to 0.649 by phase on a plate with wiggle amplitude 0 0 1e-4
#: period 0.01, where the still plate gives e = 0.6) and a rotation, whose face points accelerate
#: towards the axis (a floor turned at period 0.2 s about an axis 2 cm below it: 0.4779 at g = 0.1
#: where the still floor gives 0.4999). Only ``linear`` at a constant velocity leaves it still;
#: ``linear/variable`` does where its velocities are constant (runtime.constant_in_time).
_SHAKING = frozenset({"wiggle", "riggle", "viblin", "vibrot", "rotate", "rotate/variable"})
#: ``dimension`` is among them: in 2d LAMMPS gives a sphere's mass still (density/disc, which sets a
#: disc's, is the engine's and read back with the atoms), and its granular forces are the same (a
#: head-on pair r 0.005 and 0.01, hertz/material viscoelastic, g 0.1, dt 2e-7: eps 0.86088418 in 2d
#: and 3d alike, the masses equal to the last digit)
#: fix_modify keywords that change what a fix reports (its energy, its virial), never its force
_FIX_MODIFY_ACCOUNTING = frozenset({"energy", "virial"})
#: Data-file sections with no bearing on a head-on contact
_DATA_IRRELEVANT = {"Velocities", "Bonds", "Angles", "Dihedrals", "Impropers", "Bond Coeffs", "Angle Coeffs",
                    "Dihedral Coeffs", "Improper Coeffs"}
#: Atom styles whose data-file Atoms lines are: atom-ID atom-type diameter density x y z [image flags]
_SPHERE_STYLES = ("sphere", "granular")
#: Commands the reader needs and their least number of words (the command included): shorter,
#: LAMMPS stops on them too
_NEEDS_WORDS = {"create_box": 2, "pair_style": 2, "pair_coeff": 3}
#: Atom styles whose particles are not spheres (LIGGGHTS' superquadric, LAMMPS' ellipsoid, ...)
_SHAPED_STYLES = ("superquadric", "ellipsoid", "line", "tri", "body")
#: LIGGGHTS particle templates whose particles are not single spheres
_SHAPED_TEMPLATES = {"particletemplate/multisphere": "clumps of spheres (multisphere)",
                     "particletemplate/superquadric": "superquadrics"}
#: Runs with different contact settings the audit reports before it refuses the deck
MAX_STAGES = 100
#: Commands that neither make atoms, nor run, nor change what the reader reads (units, atom_style and
#: soft_/hard_particles, though in _IRRELEVANT, are read): a run's ``every`` may run them
_INERT = frozenset(_IRRELEVANT - {"create_atoms", "run", "clear", "minimize", "label", "delete_atoms", "units",
                                  "replicate", "reset_atoms", "reset_atom_ids",
                                  "atom_style", "soft_particles", "hard_particles",
                                  # how often the lists are rebuilt decides whether a contact is found in
                                  # time (field round 16, n25: run 1000 every 500 "neigh_modify every 10
                                  # delay 0 check no", 0.497 printed where the second part's lists find late)
                                  "neighbor", "neigh_modify",
                                  # each changes what the later parts of a run see: a wall or fix gone, the
                                  # time step (field round 20, e03, e15: a floor unfixed and dt 2e-4 after
                                  # the first part were audited as before), the atoms' velocities or places,
                                  # the box, the step a LIGGGHTS insertion starts at, the styles read next
                                  # (partition runs a command)
                                  "unfix", "timestep", "velocity", "displace_atoms", "change_box", "region",
                                  "reset_timestep", "special_bonds", "partition", "comm_modify", "dimension",
                                  "suffix", "package", "kspace_style", "run_style"})
#: Commands after which LAMMPS makes its ghost atoms anew (pbc, exchange, borders) without building
#: its neighbour lists: a run with pre no then uses lists that index the old ghosts (field round 32,
#: PB20: displace_atoms all move 0 0 0, then run pre no: 3.005689 where the pair meets across the
#: periodic boundary; change_box to the same box, balance: alike; LIGGGHTS 3.8.0 met it in time)
_REGHOSTING = {"displace_atoms", "change_box", "balance", "comm_style"}
#: Fixes that insert atoms as the run goes, into their own group (and all); LAMMPS' pour and
#: deposit name the atoms' type (fix ID group pour|deposit N type ...), LIGGGHTS' take theirs from
#: particle templates
_INSERTING_FIXES = {"pour", "deposit", "insert/pack", "insert/stream", "insert/rate/region"}


def read_executed(commands, atoms: list, radius: dict | None = None, density: dict | None = None,
                  read_file=None, restarts: list | None = None, ran: bool = False, timed: bool = False) -> Deck:
    """The settings of a deck from the commands its engine ran (:mod:`restitution.dem.deck.stream`):
    no control flow here, the engine's own; the atoms each run saw as the engine held them.

    Parameters
    ----------
    commands : list of Executed
        In the order they ran; a run's marker gives its stage number.
    atoms : list of dict
        Each run's atoms, {type: {(radius, density)}}, in the order of the runs that wrote them
        (a run whose ``snapshot`` is False wrote none: it saw the atoms of the run before).
    radius, density : dict, optional
        {type: value}, overriding what the engine holds.
    read_file : callable, optional
        ``read_file(name)``: the text of a file the deck names (a data file's Pair Coeffs), or
        raises OSError.
    restarts : list of str, optional
        What the engine held after each ``read_restart`` it ran, in order (LAMMPS' ``info system
        coeffs groups``): a restart file the deck wrote earlier in the pass is read back as the
        settings at its ``write_restart`` that LAMMPS stores, checked against it
        (:func:`read_restart`). None: every read_restart is refused.
    ran : bool
        Whether the engine made the runs (its markers wrote the atoms where each run left them,
        those its pours and deposits made included): a command after a run may then pick atoms by
        position, and no inserting fix's sizes are modelled (:attr:`Deck.ran`).
    timed : bool
        Whether the deck sets a timer (which the pass never runs), whose timeout may end a run before
        its last step: the steps the runs reach are then not known.

    Returns
    -------
    Deck

    Raises
    ------
    DeckError
        Where the deck cannot be audited as it ran, in one line naming the command: one LAMMPS
        would stop on (too few words, a line that does not split into words, a type range outside
        1..ntypes), one the reader does not map (another pair style, particles other than single
        spheres, rigid bodies, a restart file, a ``run ... every`` running anything but inert
        commands), no granular pair style, no run or end of the deck before the engine stopped, or
        more than MAX_STAGES runs with different contact settings.

    Examples
    --------
    >>> from restitution.dem.deck.stream import Executed
    >>> cmds = [Executed((None, 1), "create_box 1 b"), Executed((None, 2), "pair_style granular"),
    ...         Executed((None, 3), "pair_coeff * * hooke 10 1"), Executed((None, 4), "run 1", 0)]
    >>> deck = read_executed(cmds, [{1: {(0.5, 2.0)}}])
    >>> deck.stages[0][1].radius, deck.stages[0][1].density
    ({1: 0.5}, {1: 2.0})
    """
    deck = Deck(held={}, ran=ran)     # the engine holds the atoms: their sizes are never read from the deck
    done = 0
    # whether the last command read was a run that joined the last stage and nothing read since:
    # a run then joins it too (a loop's 10 000 runs, each key of the settings computed once)
    same = False
    # A loop's pass that defines its pours again (new seeds) and runs: the pours read since the
    # last run (seeds aside; None once anything else is read), and those before it where that run
    # was recorded in the last stage. Each of these commands, and the run with the atoms held,
    # overwrites the reader's state with what its own words or the same atoms say, so a pass equal
    # to the one before leaves the state, hence the key, as that pass did: the run joins the stage,
    # and the pass's pours, held back while they repeat the last pass's, are not read at all.
    block: list | None = []
    last_block: list | None = None
    deposited_ran: set = set()     # types a fix deposit has run for
    made: dict = {}                # type -> the sizes of the atoms LAMMPS pours made in the runs so far
    written: dict = {}             # restart file -> the settings at its write_restart (restart_state)
    data_written: dict = {}        # data file a write_data wrote -> whether pours had made atoms by then
    halting = timed                # a fix halt defined (a timer set): the step the runs reach is not known
    infos = iter(restarts or ())
    pending: list = []
    moved_since = False            # a run has gone: the atoms are where it left them, never the pass
    stepped = False                # a run has made a step since the last clear
    stepped_ever = False           # one has, clear or not (a restart file may hold the atoms it moved)
    cleared: tuple = ({}, {})      # active and defined (below) as the last clear found them
    boxed = False                  # a simulation box is defined
    min_style = "cg"               # the minimizer in force (the engines' default)
    defined: dict = {}             # (region|variable, name) -> the words that last defined it
    active: dict = {}              # the fixes defined now, ID -> their words (a deposit still in force makes more
                                   # atoms; a group or move/mesh they use changed between runs is said)
    placed: set = set()            # groups picked by where the atoms were, after a run
    stepless = None                # the first run that made no step (run 0)
    last_run = max((n for n, c in enumerate(commands) if c.stage is not None), default=-1)
    for position, cmd in enumerate(commands):
        try:
            split = words(cmd.text)
        except ScriptError as why:
            raise DeckError(place(cmd.loc), cmd.text, str(why)) from None
        # a minimize is judged by the runs before it, not by its own steps: it moves the atoms at
        # once, so one after a run that made a step changes a contact under way (field round 45,
        # B60: run 300, minimize, run 2000: LAMMPS 0.0053 where 0.4149 was printed with no word)
        before = stepped
        if split and split[0] in ("run", "minimize"):
            moved_since = True
            # a run 0 makes no step: no contact is under way after it that was not before it
            steps = number_or_none(split[1]) if len(split) > 1 else None
            # nor a minimize before any run: it ends with the atoms where their forces balance, no
            # contact under way (field round 46, Z17: velocity lines after one were said to change one)
            stepped = stepped or split[0] == "run" and ("upto" in split or steps != 0)
            stepped_ever = stepped_ever or stepped
            if split[0] == "minimize" and min_style in _AT_REST_MINIMIZERS:
                deck.unknown.append((*cmd.loc, cmd.text, AT_REST.format(style=min_style)))
        elif split and split[0] == "min_style" and len(split) > 1:
            min_style = split[1]
        elif split and moved_since and not ran and split[0] in ("group", "set", "delete_atoms"):
            _where_the_run_left(split, placed, cmd)
        elif split and split[:1] == ["group"] and len(split) > 2 and split[2] == "dynamic":
            placed.add(split[1])     # its members change as the runs move the atoms
        if split and split[0] == "processors" and boxed:
            # never run in the pass (the audit's engine has one process), so the engine's own stop
            # is the reader's to say (field round 46, lists: rows printed for a deck LAMMPS stops on)
            raise DeckError(place(cmd.loc), cmd.text, f"{deck.code} stops here: Processors command after simulation "
                                                      "box is defined")
        if split and split[0] in ("create_box", "read_data", "read_restart", "clear"):
            boxed = split[0] != "clear"
        if split and cmd.unset and not made and not deposited_ran:
            # no atom in the pass, and no pour or deposit has made any in the runs before: the
            # deck's own run stops here too
            raise DeckError(place(cmd.loc), cmd.text, f"LAMMPS stops here: {GUARDED[split[0]]}")
        if split and split[0] == "set":
            _resized(deck, deposited_ran)
            if any(k in _RETYPE for k, _ in _set_keywords(split)):
                # its members keep their group under their new type
                for name, static in deck.groups.items():
                    if static and name not in deck.empty_groups:
                        deck.partial_groups.setdefault(name, f"{place(cmd.loc)} ({cmd.text}) gave atoms another type, "
                                                             "which keep their groups")
            if made and set_poured(deck, made, split, cmd.loc, cmd.text):
                block, same = None, False        # the poured sizes changed: no pass repeats the last
        if split and split[0] == "delete_atoms" and split[1:2] == ["group"] and len(split) > 2 and moved_since:
            _deleted(deck, made, split[2], active)
        if split and split[0] == "variable" and len(split) > 2:
            _variable(deck, split)
        if split and before and position < last_run and (
                why := _kicks(split) or _wall_changed(deck, split) or _mesh_move_changed(split, active)
                or _regrouped(split, active) or _unexcluded(split)
                or _unlisted(split, active, deck.regions, deck.variables,
                             len(split) > 1 and defined.get((split[0], split[1])) == _definition(split, deck))) \
                and not any(tuple(u[:2]) == tuple(cmd.loc) and u[3] == why for u in deck.unknown):
            # a contact under way at this step is changed mid-way, and the pass (its runs skipped) cannot
            # say whether one is (field round 39, E03: velocity lv2 set every 250 steps of a 586-step
            # contact, LAMMPS 0.332 where the law's 0.4149 was printed with no word; round 40, A41: set
            # atom 2 type 1, 0.323; A17: change_box ... remap, 0.117; A59: the floor defined again 0.1 mm
            # higher, 0.620; A15: the floor unfixed, the sphere goes on through it; round 41, M53: read_data
            # add append of a sphere at the pair, 0.407; G06: a LIGGGHTS move/mesh added under a sphere on
            # the mesh, 1.142 where 0.7 was printed); a line said once
            deck.unknown.append((*cmd.loc, cmd.text, why))
        # after the check above, which judges an unfix or a group against the fixes before it
        if split and split[0] in ("region", "variable") and len(split) > 2 and split[2] != "delete":
            defined[split[0], split[1]] = _definition(split, deck)
        if split and split[0] == "fix" and len(split) > 1:
            active[split[1]] = split
        elif split and split[0] == "unfix" and len(split) > 1:
            active.pop(split[1], None)
        if split and split[0] == "write_data" and len(split) > 1:
            data_written[split[1]] = bool(made)
        if split and split[0] == "read_data" and len(split) > 1 and data_written.get(split[1]):
            # the engine's pass skips runs: the file it wrote lacks the atoms the pours made
            raise DeckError(place(cmd.loc), cmd.text, f"the deck wrote {split[1]} after poured atoms were made "
                                                      "(write_data); the engine's pass skips runs, so its file "
                                                      "lacks them: not audited")
        if split[:1] == ["set"] and "diameter" in split[3:]:
            deck.diameters_set = True  # a fix adapt resizes them again at the next set-up (_adapted_late)
        if split and split[0] in _REGHOSTING:
            deck.reghosted = (place(cmd.loc), cmd.text)
        if split and split[0] == "replicate":
            deck.replicated = (place(cmd.loc), cmd.text)
        if not split or split[0] in _ENGINE_ONLY:
            continue
        halting = halting or split[0] == "fix" and len(split) > 3 and split[3] == "halt"
        if split[0] == "run":
            # a value substituted in the run line was the pass's (its runs skipped), not the one at
            # the step the deck's runs reach (field round 24, R22: stop $(step+100) after a run):
            # its step checks are left out there
            # nor after a fix halt, which may end a run before its last step (round 24, R31, R32)
            step = None if halting or "$" in (cmd.written or "") and not deck.ran else deck.step
            if (stop := run_refused(split, step, deck.code)) is not None:
                raise DeckError(place(cmd.loc), cmd.text, f"{deck.code} stops here: {stop}")
            if halting:
                deck.step = None     # R32: run 80 upto after a halt at step 60 makes 20 steps
            deposited_ran |= {t for t, fix in deck.deposits.items() if fix is not None}
            starting = started(deck, split)
            if starting:
                block, same = None, False        # sizes come in: this run is no repeat of the last
            stepless = stepless or (cmd if deck.step is not None and _run_end(deck, split) == deck.step else None)
            # a fix adapt resizes the atoms poured before at the run's set-up; those poured in
            # the run where it acts every N steps, after it (LAMMPS measured)
            resized = adapt_poured(deck, made, cmd.loc, cmd.text, during=False)
            for t, sizes in deck.pours.values():
                made.setdefault(t, set()).update(sizes)
            repour(deck, made, resized | starting | adapt_poured(deck, made, cmd.loc, cmd.text, during=True))
        elif split[0] == "clear":
            # a new deck begins: no contact, fix, region or variable of the old one goes on, and its
            # first commands are not run between runs (a deck run again after clear: its
            # create_atoms and velocity were each said to change a contact under way)
            deposited_ran, made = set(), {}
            stepped = moved_since = False
            min_style = "cg"
            cleared = active, defined
            active, defined, placed = {}, {}, set()
        elif split[0] == "read_restart":
            # the atoms come back where a run left them: a contact under way there goes on, and what
            # is defined next is weighed against the fixes, regions and variables in force before
            stepped = moved_since = stepped_ever
            if stepped_ever:
                active, defined = dict(cleared[0]), dict(cleared[1])
        plain_run = split[0] == "run" and "every" not in split
        if cmd.stage is None and block is not None and (pour := _pour_again(split)) is not None:
            block = block + [pour]
            if last_block is not None and block == last_block[:len(block)]:
                pending.append((split, cmd))
                same = False
                continue
        elif cmd.stage is None:
            block = None
        elif cmd.snapshot is False and plain_run and block and block == last_block:
            deck.stages[-1][0].append((cmd.loc, cmd.text))     # the atoms of the run before, held again
            block, pending = [], []
            continue
        for held_back, held_cmd in pending:      # the pass differs from the last: its pours, in turn
            _execute(deck, held_back, held_cmd.text, held_cmd.loc, read_file)
        pending = []
        if cmd.stage is not None and cmd.snapshot is not False:
            if done >= len(atoms):
                # the engine was stopped before this run wrote its atoms (its budget ran out): what
                # it held from here on is unknown, so the audit ends at the last run it saw
                break
            _held(deck, atoms[done], radius or {}, density or {})
            done += 1
            same = False
        elif cmd.stage is not None and same and plain_run:
            deck.stages[-1][0].append((cmd.loc, cmd.text))
            continue
        elif cmd.stage is not None and done:
            # a run that wrote no atoms saw those of the run before (the engine found nothing in
            # between that changes them): held again, over what the commands since say of sizes
            _held(deck, atoms[done - 1], radius or {}, density or {})
        runs = (len(deck.stages), len(deck.stages[-1][0]) if deck.stages else 0)
        if split[0] == "write_restart" and len(split) > 1:
            written[split[1]] = restart_state(deck, made, deposited_ran)
        if split[0] == "read_restart" and restarts is not None and len(split) > 1:
            made = read_restart(deck, split, cmd.loc, cmd.text, written.get(split[1]), next(infos, None))
            deposited_ran = set()
        else:
            pours = dict(deck.pours)
            _execute(deck, split, cmd.text, cmd.loc, read_file)
            # a pour gone (or defined anew) adds its size no more
            repour(deck, made, {t for key, (t, _) in pours.items() if deck.pours.get(key) != pours[key]})
            if deck.ended:
                break                    # the deck quit after this run's first part: nothing after it runs
        same = plain_run and runs == (len(deck.stages), len(deck.stages[-1][0]) - 1 if deck.stages else -1)
        if cmd.stage is not None:
            recorded = bool(deck.stages) and runs != (len(deck.stages), len(deck.stages[-1][0]))
            last_block, block = (block if plain_run and recorded else None), []
    for held_back, held_cmd in pending:          # pours after the last run: settings no run used
        _execute(deck, held_back, held_cmd.text, held_cmd.loc, read_file)
    if deck.unmapped and not deck.stages:
        raise DeckError(*deck.unmapped)  # the deck's pair style, though no run used it
    if not deck.stages:
        if not atoms:
            # no run and no end reached: "no particle" would be a guess, never a reading
            raise DeckError("deck", None, "the engine stopped (a quit, or the audit's time budget) before any "
                                          "run or the deck's end showed the particles it holds: not audited")
        _held(deck, atoms[-1], radius or {}, density or {})
        repour(deck, {}, started(deck, None))
        _uninserted_templates(deck)
        if stepless is not None:
            # field round 19, c29: a deck whose only run is run 0 was audited as set up, unsaid
            deck.unknown.append((*stepless.loc, stepless.text, "makes no step, as every run of the deck: no contact "
                                 "happens in them; audited as the deck sets up, with the spheres its inserting "
                                 "fixes would make"))
    for d in [deck] + [snap for _, snap, _ in deck.stages]:
        for t, r in (radius or {}).items():
            d.radius[int(t)] = r
        for t, rho in (density or {}).items():
            d.density[int(t)] = rho
        for t in {int(t) for t in [*(radius or {}), *(density or {})]} & set(d.sizes):
            # a size given for a type of several: what it does not give stays the type's own
            sizes = {(d.radius.get(t, r), d.density.get(t, rho)) for r, rho in d.sizes.pop(t)}
            if len(sizes) > 1:
                d.sizes[t] = sorted(sizes)
            else:
                d.radius[t], d.density[t] = sizes.pop()
                d.sampled.pop(t, None)
    if not any(d.code for d in [deck] + [snap for _, snap, _ in deck.stages]):
        raise DeckError("pair_style", None, "the deck has no pair_style granular (LAMMPS) or pair_style gran "
                                            "(LIGGGHTS) line")
    return deck


#: What a LAMMPS restart file stores of the settings the reader keeps (22 Jul 2025, measured after
#: write_restart, clear, read_restart: the pair style and its coefficients, the time step, groups,
#: type labels, special_bonds; not fixes, regions, neigh_modify exclusions or molecule templates):
#: a read_restart starts afresh as clear does, with these of the settings at the write
_RESTORED = ("code", "ntypes", "units", "dimension", "atom_style", "atom_style_loc", "style", "style_line",
             "unmapped", "reset", "coeffs", "gran", "cutoff", "hybrid", "substyle", "hybrid_one", "none_at",
             "granular_of", "others",
             "idle", "groups", "empty_groups", "filled_groups", "partial_groups", "labels", "dt", "atoms", "present",
             "present_unknown", "bonds", "special_lj", "bond_forces", "periodic")
#: What a LIGGGHTS 3.8.0 restart file stores of them (measured after write_restart, clear,
#: read_restart): the pair style with its normal model (a hooke/stiffness pair style not given again
#: stops the next run for want of its kn, a fix property/global, which the restart does not hold)
#: and its coefficients, groups; not the time step (LIGGGHTS' default, 1e-8 in si, after the read),
#: nor any fix (materials, walls, meshes, templates)
_RESTORED_LIGGGHTS = tuple(name for name in _RESTORED if name != "dt") + (
    "model", "limit_force", "absolute_damping", "cohesion")


def restart_state(deck: Deck, made: dict, deposited: set) -> tuple:
    """The settings a ``write_restart`` stores (:data:`_RESTORED`), the sizes of the atoms LAMMPS
    pours had made by then (in the file, never in the engine's pass: its runs are skipped) and the
    types a fix deposit had made atoms of.

    Parameters
    ----------
    deck : Deck
        The settings at the write.
    made : dict
        Type -> {(radius, density)} of the atoms the pours had made.
    deposited : set
        The types a fix deposit had made atoms of.

    Returns
    -------
    tuple
        (the stored settings by field name, ``made``, ``deposited``), copies.

    Examples
    --------
    >>> state, made, deposited = restart_state(Deck(ntypes=2, regions={"r": []}), {}, set())
    >>> state["ntypes"], "regions" in state
    (2, False)
    """
    kept = _RESTORED_LIGGGHTS if deck.code == "LIGGGHTS" else _RESTORED
    return ({name: copy.deepcopy(getattr(deck, name)) for name in kept}, copy.deepcopy(made), set(deposited))


def _restart_info(info: str) -> dict:
    """What LAMMPS' ``info system coeffs groups`` says it holds: units, atom style, number of types,
    pair style, time step and step number, the pairs whose coefficients are set, the groups, whether
    a boundary of the box is periodic."""
    found: dict = {"set": set(), "unset": set(), "groups": set()}
    for line in info.splitlines():
        if m := re.match(r"Units\s*=\s*(\S+)", line):
            found["units"] = m.group(1)
        elif m := re.match(r"Atom style\s*=\s*(\S+)", line):
            found["atom_style"] = m.group(1)
        elif m := re.match(r"Atoms\s*=\s*\d+,\s*types\s*=\s*(\d+),\s*style\s*=\s*(\S+)", line):
            found["ntypes"], found["pair_style"] = int(m.group(1)), m.group(2)
        elif m := re.match(r"Current timestep size\s*=\s*(\S+)", line):
            found["dt"] = float(m.group(1))
        elif m := re.match(r"Current timestep number\s*=\s*(\d+)", line):
            found["step"] = int(m.group(1))
        elif m := re.match(r"\s*(\d+)\s+(\d+):\s*is (not )?set", line):
            found["unset" if m.group(3) else "set"].add((int(m.group(1)), int(m.group(2))))
        elif m := re.match(r"Group\[\s*\d+\]:\s*(\S+)", line):
            found["groups"].add(m.group(1))
        elif m := re.match(r"Boundaries\s*=\s*(.+)", line):
            found["periodic"] = "p" in m.group(1)
    return found


#: LAMMPS' granular pair styles that a restart restores with no cutoff, which the deck's own
#: pair_style sets again (field round 32: R04 granular, RP05 gran/hooke/history)
_UNCUT_BY_RESTART = frozenset({"granular", "gran/hooke", "gran/hooke/history", "gran/hertz/history"})


def read_restart(deck: Deck, words: list, loc, line: str, written: tuple | None, info: str | None) -> dict:
    """read_restart FILE (LAMMPS, LIGGGHTS): the settings the deck had at its ``write_restart FILE``
    that a restart stores (:data:`_RESTORED`, :data:`_RESTORED_LIGGGHTS`), the rest afresh as after
    clear, checked against what the engine says it holds after the read (``info``: units, atom
    style, types, pair style, groups; LAMMPS' also the time step and the pairs whose coefficients
    are set); the atoms are the engine's at the next run, with those the pours had made before the
    write.

    Parameters
    ----------
    deck : Deck
        Changed in place: the settings after the read.
    words : list of str
        The read_restart command's words (the file as the engine read it).
    loc : tuple
        (file or None, line number) of the command.
    line : str
        The command, for the refusal.
    written : tuple or None
        :func:`restart_state` at the deck's write_restart of that file, None where it wrote none.
    info : str or None
        The engine's ``info system coeffs groups`` (LIGGGHTS: ``info system groups``) after the read.

    Returns
    -------
    dict
        The sizes of the atoms the pours had made by the write, by type.

    Raises
    ------
    DeckError
        Where the file is not one the deck wrote earlier in the pass (a binary file the reader does
        not read), the restart holds atoms a fix deposit made, or what LAMMPS holds is not what the
        deck had at the write.

    Examples
    --------
    >>> deck = Deck(ntypes=1, units="si", atom_style="sphere", dt=1e-6, style="granular",
    ...             style_line=(((None, 3), "pair_style granular")), coeffs={(1, 1): ((None, 4), ["pair_coeff"])},
    ...             regions={"r": ["region"]})
    >>> info = ("Units = si\\nAtom style = sphere\\nAtoms = 1, types = 1, style = granular\\n"
    ...         "Current timestep size = 1e-06\\n     1      1: is set\\nGroup[ 0]: all (static)\\n")
    >>> after = Deck()
    >>> read_restart(after, ["read_restart", "f"], (None, 9), "read_restart f", restart_state(deck, {}, set()), info)
    {}
    >>> after.coeffs == deck.coeffs, after.regions
    (True, {})
    """
    where = place(loc)
    held = _restart_info(info) if info is not None else {}
    if written is None and "ntypes" in held:
        # a restart the deck did not write (shipped beside it, or written by a separate init deck):
        # neither engine says what contact coefficients it holds (LAMMPS' write_coeff writes none for
        # the granular styles), so the deck's own lines after the read decide, and a pair whose
        # coefficients only the file holds is not audited (field round 18, D3: b09 refused though it
        # set every pair again). LIGGGHTS' account has no time step (after the read it has its units'
        # default) and no coefficients; its restart holds the pair style with its model and no fix,
        # so a pair style not given again leaves the pairs not audited (field round 47a, M10 and
        # CFDEM's Ergun run decks R03-R06, which give each again: refused, where LIGGGHTS measured
        # 0.500006, 0.295686)
        fresh = Deck(unknown=deck.unknown, ignored=deck.ignored, stages=deck.stages)
        deck.__dict__.update(fresh.__dict__)
        deck.units, deck.atom_style, deck.ntypes, deck.dt = held.get("units"), held.get("atom_style"), \
            held["ntypes"], held.get("dt")
        deck.held, deck.atoms = {}, True
        if "dt" not in held:
            _as_read(deck, held, "LIGGGHTS")
            n = held["ntypes"]
            deck.restart_pairs = (loc, line, f"pair_style {held.get('pair_style')} (its model the file's)",
                                  {(i, j) for i in range(1, n + 1) for j in range(i, n + 1)})
            return {}
        if held.get("pair_style") == "granular":
            # LAMMPS restores the style (its models come per pair_coeff line), which the deck need not
            # give again (its manual; field round 24, V33): read as given here
            _pair_style(deck, ["pair_style", "granular"], where, line, loc)
        _as_read(deck, held, "LAMMPS")
        if held.get("pair_style", "none") != "none" and held["set"]:
            deck.restart_pairs = (loc, line, held["pair_style"], set(held["set"]))
        return {}
    if written is None:
        raise DeckError(where, line, f"read_restart reads {words[1]}, which the deck did not write before (with "
                                     "write_restart, in the engine's pass): neither engine gives an account of the "
                                     "contact coefficients a restart file holds (LAMMPS' write_coeff writes none for "
                                     "the granular styles, its info only whether each pair is set), not audited")
    state, made, deposited = written
    engine = state["code"] or "LAMMPS"
    if info is None:
        raise DeckError(where, line, f"{engine} gave no account of what it holds after the read (the audit's info): "
                                     "not audited")
    if deposited:
        raise DeckError(where, line, f"the restart file holds the atoms fix deposit made of type "
                                     f"{min(deposited)} in the runs before its write, which the engine's pass (its "
                                     "runs skipped) never made: their sizes are not followed, not audited")
    style_words = state["style_line"][1].split() if state["style_line"] else []
    dt = state["dt"] if state.get("dt") is not None else DEFAULT_DT.get(state["units"])
    set_before = set(state["coeffs"]) | set(state["others"]) | set(state["idle"])
    checks = [("units", held.get("units"), state["units"]),
              ("atom style", held.get("atom_style"), (state["atom_style"] or "atomic").split()[0]),
              ("number of types", held.get("ntypes"), state["ntypes"]),
              ("pair style", held.get("pair_style"), style_words[1] if len(style_words) > 1 else "none"),
              ("groups", held["groups"], {"all", *state["groups"]})]
    for what, holds, reader in checks:
        if holds != reader:
            raise DeckError(where, line, f"after the read {engine} holds {what} {_shown(holds)}, where the deck had "
                                         f"{_shown(reader)} at its write_restart: what the file holds is not "
                                         "followed, not audited")
    # LIGGGHTS' restart holds no time step, and its info says none: after the read it has its default
    if "dt" in state and (dt is None or held.get("dt") is None or abs(held["dt"] - dt) > 1e-5 * abs(dt)):
        raise DeckError(where, line, f"after the read LAMMPS holds time step {held.get('dt')}, where the deck had "
                                     f"{dt} at its write_restart: not audited")
    if held["set"] - set_before:
        pairs = ", ".join(f"{i} {j}" for i, j in sorted(held["set"] - set_before))
        raise DeckError(where, line, f"after the read {engine} holds coefficients for types {pairs}, which the deck "
                                     "had not set at its write_restart: not audited")
    fresh = Deck(unknown=deck.unknown, ignored=deck.ignored, stages=deck.stages)
    deck.__dict__.update(fresh.__dict__)
    for name, value in copy.deepcopy(state).items():
        setattr(deck, name, value)
    _as_read(deck, held, engine)
    for key in held["unset"]:
        # a sub-style whose coefficients a restart does not store: LAMMPS holds none for the pair
        deck.coeffs.pop(key, None)
        deck.others.pop(key, None)
        deck.idle.pop(key, None)
    deck.held = {}
    for t, sizes in made.items():
        deck.poured[t] = set(sizes)
        pour_into(deck, t, set())
    return copy.deepcopy(made)


def _as_read(deck: Deck, held: dict, engine: str) -> None:
    """What any read_restart leaves, as the engine says it holds (``held``): the file's step (a
    run's start, stop or upto is checked against it: field round 24, R06), the file's boundary,
    whatever a boundary command before the read said (field round 29, N11 and N25: an f f f box
    read as periodic), and in LAMMPS no global cutoff through the file, a pair_style granular
    CUTOFF's included (field round 32, R04)."""
    deck.step = held.get("step")
    deck.periodic = held.get("periodic", deck.periodic)
    if engine == "LAMMPS" and held.get("pair_style") in _UNCUT_BY_RESTART:
        deck.cutoff, deck.restored_cut = 0.0, True


def _shown(value) -> str:
    """A value as a refusal names it (a set of groups sorted)."""
    return " ".join(sorted(value)) if isinstance(value, set) else str(value)


def _pour_again(split: list) -> tuple | None:
    """A fix pour or deposit's words without its seed (which the reader does not read); None for
    any other command."""
    seed = SEEDED.get(split[3]) if split[0] == "fix" and len(split) > 3 else None
    return None if seed is None else tuple(split[:seed] + split[seed + 1:])


#: Commands whose effect on the atoms the engine reports itself (the sizes a run sees), and the
#: control flow the engine ran: not read again
_ENGINE_ONLY = {"set", "variable", "if", "jump", "label", "next", "include", "quit", "mass"}


def _held(deck: Deck, atoms: dict, radius: dict, density: dict) -> None:
    """The atoms a run sees, as the engine held them: each type's radius and density where all its
    atoms share one; several (a type of several sizes) in ``sizes``; a type without atoms
    keeps what an inserting fix gives it (a pour) or none (walls only, or unused)."""
    if deck.ran:
        # the runs made: a type whose atoms the runs or the commands since retyped, deleted or lost
        # has none at this run, whatever size it had at the last
        gone = set(deck.held or ()) - set(atoms)
    else:
        # runs skipped: a type the engine held at the last run and holds no more lost its atoms to
        # the commands since (a delete_atoms of a group by ID, a set type), unless an inserting fix
        # may make more of it, whose spheres the pass never holds (field round 27, G11, E33: a
        # delete_atoms group of IDs left the type's pairs printed)
        inserting = set().union(*(t for t in deck.inserts if t is not None)) if deck.inserts else set()
        if any(t is None for t in deck.inserts):
            inserting = set(deck.held or ())
        sources = inserting | set(deck.poured) | {t for t, _ in deck.pours.values()} | set(deck.deposits)
        gone = set(deck.held or ()) - set(atoms) - sources
    for t in gone:
        for known in (deck.radius, deck.density, deck.sizes, deck.sampled):
            known.pop(t, None)
    deck.held = {t: sorted(v) for t, v in atoms.items()}
    deck.seen_before, deck.seen = deck.seen, atoms
    deck.once = {t: set(v.once) for t, v in atoms.items() if getattr(v, "once", None)}
    deck.atoms = deck.atoms or bool(atoms)
    deck.present |= set(atoms)
    for t, sizes in atoms.items():
        # a pour's or deposit's spheres arrive as its run goes, never in the engine's skipped run: with the held
        sizes = set(sizes) | deck.poured.get(t, set())
        radii = {r for r, _ in sizes}
        dens = {rho for _, rho in sizes}
        deck.missing.pop(t, None)
        deck.sizes.pop(t, None)
        deck.sampled.pop(t, None)
        if min(radii) <= 0:
            deck.radius.pop(t, None)
            deck.missing[t] = f"type {t} holds point particles (radius 0), which have no contact radius"
        elif any(rho is None for _, rho in sizes):
            deck.radius.pop(t, None)
            deck.missing[t] = (f"type {t} holds a sphere of radius {min(radii):g}, whose volume is 0 in floating "
                               "point: it has no density")
        elif len(radii) == 1 and len(dens) == 1:
            deck.radius[t], deck.density[t] = radii.pop(), dens.pop()
        else:
            deck.radius.pop(t, None)
            deck.density.pop(t, None)
            deck.sizes[t] = _sampled(sorted(set(sizes)))
            if len(deck.sizes[t]) < len(set(sizes)):
                deck.sampled[t] = len(set(sizes))
    for t, why in deck.resized.items():
        for known in (deck.radius, deck.density, deck.sizes, deck.sampled):
            known.pop(t, None)
        deck.missing[t] = why
    for t in [t for t, made in deck.deposits.items() if made is None]:
        for known in (deck.radius, deck.density, deck.sizes, deck.sampled):
            known.pop(t, None)
        deck.missing[t] = (f"a set after a run may resize the atoms a fix deposit made of type {t} in that run, "
                           "which the engine's pass (its runs skipped) never made")


def _execute(deck: Deck, words: list, line: str, loc, read_file) -> None:
    """One command that ran (the script's control flow is the engine's), as far as a head-on
    contact is concerned."""
    where = place(loc)
    cmd = words[0]
    words = unlabeled(deck, words, where, line)
    if cmd in _NEEDS_WORDS and len(words) < _NEEDS_WORDS[cmd]:
        raise DeckError(where, line, f"{cmd} needs at least {_NEEDS_WORDS[cmd] - 1} argument(s)")
    elif cmd == "labelmap" and len(words) >= 2:
        labelmap(deck, words, where, line)
    elif cmd == "create_box":
        deck.ntypes = atom_type(words[1], where, line, "the number of types")
    elif cmd == "shell" and words[1:2] == ["putenv"]:
        # the engine sets them itself (the pass runs it): a later getenv reads these
        deck.putenv.update(w.split("=", 1) for w in words[2:] if "=" in w)
    elif cmd == "read_data" and len(words) >= 2:
        _read_data(deck, words, where, line, read_file)
        deck.atoms = True
    elif cmd == "create_atoms":
        deck.atoms = True
        if len(words) > 1 and words[1].isdigit():
            deck.present.add(int(words[1]))
            _made_after(deck, {int(words[1])}, f"{where} ({line})")
        else:
            deck.present_unknown = True
            _made_after(deck, None, f"{where} ({line})")
    elif cmd == "run":
        ending = _run_every(words, where, line)
        deck.ended = ending == "quits"
        _not_set_up(deck, words, where, line)
        _adapted_late(deck, where, line)
        if _no_step(deck, words):
            return                        # a run of 0 steps: no contact happens in it (field round 19, C1)
        if deck.inserting:
            # the atoms inserted during this run are no members of the groups defined before it
            for inserted in deck.inserts:
                _made_after(deck, inserted, f"{where} ({line}), where an inserting fix makes atoms", inserting=True)
        _uninserted_templates(deck)
        _none_not_kept(deck)
        _stage(deck, loc, line)
        if ending == "may quit":
            deck.may_end = (where, line)
        _moved_in_run(deck, loc, line)
        if deck.inserting:
            deck.atoms = True
            _inserted(deck)
    elif cmd == "reset_timestep" and len(words) >= 2:
        step = number_or_none(words[1])
        deck.step = int(step) if step is not None else None
    elif cmd == "minimize":
        deck.step = None
    elif cmd == "clear":
        # LAMMPS starts afresh (box, atoms, styles, coefficients); the runs before it stay stages
        # the process's environment outlives a clear, and so does how the pass reads the atoms: from
        # the engine (held, never from the deck's own sizes), from runs it made for real or not
        # (field round 26, CL01-CL05, CL22: a pour after a clear was read as the hand reader's, its
        # sizes lost to the atoms held at the run; CL25, CL28: atoms lost in runs made for real)
        fresh = Deck(unknown=deck.unknown, ignored=deck.ignored, stages=deck.stages, environment=deck.environment,
                     putenv=deck.putenv, held=None if deck.held is None else {}, ran=deck.ran)
        deck.__dict__.update(fresh.__dict__)
    elif cmd == "read_restart":
        raise DeckError(where, line, "read_restart: the types, sizes and coefficients come from a binary restart "
                                     "file, which the reader does not read")
    elif cmd == "atom_style" and len(words) >= 2:
        deck.atom_style, deck.atom_style_loc = " ".join(words[1:]), loc
        if words[1] in _SHAPED_STYLES:
            raise DeckError(where, line, f"atom_style {words[1]}: its particles are not spheres, and the reader "
                                         "audits the head-on contact of spheres only")
    elif cmd == "pair_style":
        _pair_style(deck, words, where, line, loc)
    elif cmd == "pair_coeff":
        _pair_coeff(deck, words, where, line, loc)
    elif cmd == "set" and len(words) >= 3:
        _set(deck, words, where, line, loc)
    elif cmd == "fix" and len(words) >= 4:
        _fix(deck, words, where, line, loc)
    elif cmd == "group" and len(words) >= 3:
        _group(deck, words)
    elif cmd == "units" and len(words) >= 2:
        deck.units = words[1]
        # both engines set the units' default time step here, whatever a timestep before said (field
        # round 19, C3: c13, L30 gave steps per contact at a dt the engines no longer used)
        deck.dt, deck.dt_reset = None, ()
    elif cmd == "dimension" and len(words) >= 2 and words[1] in ("2", "3"):
        deck.dimension = int(words[1])       # fix gravity's direction depends on it
    elif cmd == "unfix" and len(words) >= 2:
        _unfix(deck, words[1])
    elif cmd == "fix_modify" and _accounting(words):
        pass
    elif cmd == "neighbor" and len(words) >= 2:
        try:
            deck.skin = float(words[1])
        except ValueError:
            deck.skin = None
        deck.neighbor_style = words[2] if len(words) > 2 else deck.neighbor_style
    elif (faces := boundary_faces(words)) is not None:
        deck.periodic = "p" in faces
    elif cmd == "velocity" and len(words) >= 3:
        still = words[2] == "set" and all(w in ("0", "0.0", "NULL") for w in words[3:6]) and len(words) >= 6
        if not still:
            deck.velocities = deck.velocities + [(loc, line, words[1])]
    elif cmd == "neigh_modify":
        neigh_modify(deck, words, loc, line)
    elif cmd == "special_bonds":
        special_bonds(deck, words, where, line)
    elif cmd == "create_bonds":
        deck.bonds = (loc, line)
    elif cmd in _BONDED_STYLES and len(words) >= 2:
        kind = cmd.removesuffix("_style")
        deck.bond_forces = {k: v for k, v in deck.bond_forces.items() if k != kind}
        if not set(words[1:]) <= {"zero", "none", "nocoeff"}:
            deck.bond_forces[kind] = (loc, line)
    elif cmd == "timestep" and len(words) >= 2:
        deck.dt = number(words[1], where, line)
        deck.dt_reset = ()           # a step known again, whatever a fix dt/reset left
    elif cmd == "region" and len(words) >= 3:
        # read back by a region wall (its surfaces' curvature), which a run may see
        if words[2] == "delete":
            deck.regions.pop(words[1], None)
        else:
            deck.regions[words[1]] = list(words)
    elif cmd == "lattice":
        deck.lattice = list(words)
    elif cmd == "molecule" and len(words) >= 3:
        deck.templates[words[1]] = _template(words, where, line, read_file)
    elif cmd == "ndx2group" and len(words) > 2:
        # the groups named take their atoms from the index file (the engine reads it; field round 20,
        # z36): members by number, not by type
        for name in words[2:]:
            deck.groups[name] = None
            deck.empty_groups.discard(name)
            deck.partial_groups.pop(name, None)
    elif cmd in ("soft_particles", "hard_particles") and len(words) >= 2:
        setattr(deck, cmd.split("_")[0], words[1] == "yes")
    elif cmd not in _IRRELEVANT:
        deck.unknown.append((*loc, line, "not understood"))


def _accounting(words: list) -> bool:
    """Whether a ``fix_modify ID keyword value ...`` only sets what the fix reports."""
    pairs = words[2:]
    return bool(pairs) and len(pairs) % 2 == 0 and all(k in _FIX_MODIFY_ACCOUNTING for k in pairs[::2])


#: LAMMPS' hybrid pair styles: each pair's force from the sub-style its pair_coeff names (hybrid),
#: or the sum of all those naming it (hybrid/overlay)
_HYBRID = ("hybrid", "hybrid/overlay")


def _hybrid(deck: Deck, words: list, where: str, line: str) -> list:
    """pair_style hybrid[/overlay] S1 args S2 args ...: the pair_style commands of its granular
    sub-styles, which pair_coeff lines naming them set: one, or an older gran/* style and granular
    (each sets its own part of the deck: the older law, granular's cutoff). A sub-style's arguments
    are numbers, NULL or limit_damping up to the next sub-style's name."""
    grans = [k for k, w in enumerate(words) if k >= 2 and w in PAIR_STYLES]
    names = [words[k] for k in grans]
    older = [name for name in names if name != "granular"]
    if not grans or len(set(older)) < len(older) or len(older) > 1 or \
            any(PAIR_STYLES[name].ENGINE != "LAMMPS" for name in names[1:]):
        raise DeckError(where, line, f"pair_style {words[1]} with {len(grans) or 'no'} granular sub-styles "
                                     f"({' '.join(names) or 'none'}): the reader maps one, or one older gran/* "
                                     "style beside granular, or several granular")
    if names.count("granular") > 1:
        # LAMMPS numbers the instances of one sub-style, and pair_coeff names one as "granular N"
        count = iter(range(1, len(names) + 1))
        names = [name if not name.startswith("granular") else f"granular {next(count)}" for name in names]
    substyles = []
    for k in grans:
        n = k + 1
        while n < len(words) and (words[n] in ("NULL", "limit_damping") or re.fullmatch(r"[-+.\deE]+", words[n])):
            n += 1
        substyles.append(["pair_style", *words[k:n]])
    substyles.sort(key=lambda sub: sub[1] == "granular")     # granular's cutoff last: the older resets it
    deck.hybrid, deck.substyle, deck.others, deck.idle = words[1], " and ".join(names), {}, {}
    deck.granular_of, deck.none_at = {}, {}
    # the granular sub-style's own words are all the style has: one sub-style alone
    deck.hybrid_one = len(substyles) == 1 and len(words) == len(substyles[0]) + 1
    return substyles


def _pair_style(deck: Deck, words: list, where: str, line: str, loc) -> None:
    deck.style_line = (loc, line)
    # an OpenMP or OPT variant typed by its name computes the plain style's forces, as the plain name
    # under `suffix omp` does (field round 19, c26: gran/hertz/history/omp was refused)
    if len(words) > 1 and words[1].endswith(("/omp", "/opt")) and words[1].rsplit("/", 1)[0] in PAIR_STYLES:
        words = [words[0], words[1].rsplit("/", 1)[0], *words[2:]]
    substyles = [words]
    # a hybrid style issued again, or replaced, or replacing another: LAMMPS drops every coefficient
    # (22 Jul 2025 measured: hybrid then the same hybrid, hybrid then granular, granular then hybrid
    # each stop the next run on "All pair coeffs are not set"; granular issued again keeps them)
    hybrid_again = bool(deck.style) and (bool(deck.hybrid) or words[1] in _HYBRID)
    if len(words) > 2 and words[1] in _HYBRID:
        substyles = _hybrid(deck, words, where, line)
        words = substyles[0]
    else:
        deck.hybrid, deck.substyle, deck.others, deck.idle = "", "", {}, {}
        deck.granular_of, deck.hybrid_one, deck.none_at = {}, False, {}
    style = " ".join(sub[1] for sub in substyles)
    if deck.restart_pairs and (style != deck.restart_pairs[2] or len(substyles) > 1):
        deck.restart_pairs = ()       # another style: the file's coefficients are gone
    if deck.style and (style != deck.style or hybrid_again):
        # LAMMPS keeps the coefficients for the same style (its settings change); another style
        # starts without any, and LAMMPS stops at the next run unless new pair_coeff lines follow
        if deck.coeffs or deck.gran:
            deck.reset = (loc, line)
        deck.coeffs, deck.gran = {}, {}
    deck.style = style
    if len(substyles) > 1:
        deck.unmapped = ()
        deck.code = PAIR_STYLES[words[1]].ENGINE
        for sub in substyles:
            PAIR_STYLES[sub[1]].pair_style(deck, sub, where, line)
        return
    if style == "none":
        # no force between any two atoms (a settling stage: field round 19, a10 was refused whole):
        # its runs are no stage, as runs before any pair style are not
        deck.unmapped, deck.code = (), ""
        note = (*loc, line, "no force between spheres: the runs under it are no stage of the audit, and a wall met "
                            "only in them is not audited")
        if note not in deck.unknown:
            deck.unknown.append(note)
        return
    if style not in PAIR_STYLES:
        deck.unmapped = (where, line, f"pair_style {style} is not mapped (the reader maps "
                                      f"{', and '.join(d.MAPPED for d in DIALECTS.values())})")
        return
    deck.unmapped = ()
    deck.code = PAIR_STYLES[style].ENGINE
    PAIR_STYLES[style].pair_style(deck, words, where, line)


#: Sub-styles whose force is their first coefficient times a shape (soft's A, lj/cut's epsilon)
_PREFACTOR_FIRST = ("soft", "lj/cut")


def _idle(sub: str, args: list) -> bool:
    """Whether a sub-style's pair_coeff arguments give it no force at all: the zero style, or a
    prefactor of exactly 0 (LAMMPS multiplies its force by it)."""
    if sub == "zero":
        return True
    try:
        return sub in _PREFACTOR_FIRST and bool(args) and float(args[0]) == 0.0
    except ValueError:
        return False


def _pair_coeff(deck: Deck, words: list, where: str, line: str, loc) -> None:
    if deck.unmapped:
        return                           # its coefficients are the engine's to check
    if deck.code not in DIALECTS:
        if deck.restart_pairs:
            at, text, style, _ = deck.restart_pairs
            raise DeckError(where, line, f"the pair style is the one {place(at)} ({text}) read, {style}, of which "
                                         "the engine gives no account: not audited (give pair_style again after "
                                         "the read)")
        raise DeckError(where, line, "pair_coeff before a pair_style the reader maps")
    if deck.hybrid and len(words) > 3:
        sub = words[3]
        if f"{sub} 1" in deck.substyle.split(" and ") and len(words) > 4:
            # one of several instances of a sub-style, named by its number (LAMMPS stops without it)
            sub, words = f"{sub} {words[4]}", [*words[:4], *words[5:]]
        if sub in deck.substyle.split(" and "):
            # its granular sub-style (one of two: the pairs LAMMPS' loop sets now take it under hybrid,
            # or add it under hybrid/overlay, a pair of both then refused); under hybrid it gives the
            # pairs back that a none took from it (field round 26, T14: the later pair_coeff 1 2
            # granular ... was left out, the none read)
            words = [*words[:3], *words[4:]]
            DIALECTS[deck.code].pair_coeff(deck, words, where, line, loc)
            several = " and " in deck.substyle
            for key, (_, set_by) in deck.coeffs.items():
                if set_by is words:
                    if deck.hybrid == "hybrid":
                        deck.others.pop(key, None)
                        if several:
                            deck.granular_of[key] = {sub}
                    elif several:
                        deck.granular_of.setdefault(key, set()).add(sub)
            return
        else:
            # another sub-style (or none): under hybrid it replaces the granular one on these pairs,
            # under hybrid/overlay it adds its force to it
            for key in type_pairs(words[1], words[2], deck.ntypes, where, line):
                if deck.hybrid == "hybrid":
                    deck.coeffs.pop(key, None)
                    deck.granular_of.pop(key, None)
                    deck.others[key] = {sub}
                    if sub == "none":
                        deck.none_at[key] = (where, line)
                elif _idle(sub, words[4:]):
                    deck.idle.setdefault(key, set()).add(sub)
                elif sub != "none":
                    deck.others.setdefault(key, set()).add(sub)
            return
    DIALECTS[deck.code].pair_coeff(deck, words, where, line, loc)


def _none_not_kept(deck: Deck) -> None:
    """A pair of two types given ``none`` under ``pair_style hybrid`` with one sub-style alone, neither
    type's pair with itself none too: LAMMPS 22 Jul 2025 gives it the sub-style's force all the same
    (field round 26, measured head-on: T07, T17, T21, T25, T27 collided at the granular law's 0.414918;
    1 1 none alone, or 2*3 3 none, are kept: the spheres pass through), with which coefficients the
    audit does not know. Refused in one line at the run it would be audited in."""
    if deck.hybrid != "hybrid" or not deck.hybrid_one:
        return
    for (i, j), subs in sorted(deck.others.items()):
        if i != j and subs == {"none"} and deck.others.get((i, i)) != {"none"} \
                and deck.others.get((j, j)) != {"none"} and (i, j) in deck.none_at:
            where, line = deck.none_at[(i, j)]
            raise DeckError(where, line, f"types {i} {j}: none under pair_style hybrid with one sub-style alone, "
                                         "which LAMMPS does not keep for a pair of two types whose own pairs "
                                         "are not none (measured: they collide under the sub-style's law, "
                                         "with coefficients the audit does not know); not audited (use "
                                         "neigh_modify exclude type, or pair_style granular alone)")


def _run_every(words: list, where: str, line: str) -> str | None:
    """run N every M c1 c2 ...: LAMMPS runs the commands after each part of M steps, the last too
    (22 Jul 2025 measured); the engine's pass never runs them (LAMMPS' -skiprun sets the run up
    once, LIGGGHTS' marker runs one step of a run without every), so the contact they would give
    the parts after the first is nowhere in what it ran. Only inert ones (output, say) leave the
    contact as the reader reads it; NULL runs none. "quits" where a quit among them ends the deck
    after the run's first part (field round 20, e27, L93: the runs after it were audited as the
    deck's), "may quit" where an if's branch quits (whether it does depends on the run: no stage
    may follow, field round 21, c28), else None."""
    if "every" not in words:
        return None
    at = words.index("every")
    commands = words[at + 2:]
    pre_no = any(words[k:k + 2] == ["pre", "no"] for k in range(2, at))
    for command in commands:
        first = _first_not_inert(command)
        if first is None and pre_no and command.split()[:1] and command.split()[0] in _REGHOSTING:
            # inert in a part set up again; with pre no the parts after the first keep lists that
            # index the ghost atoms it made anew (a run of more parts than the pass splits: round 33, G07)
            first = command.split()[0]
        if first is not None:
            raise DeckError(where, line, f"run ... every runs {first} between the run's parts, which may change the "
                                         "contact from the second part on, and the engine's pass never runs them "
                                         "(its runs skipped or cut to one step): not audited; split the run into "
                                         "runs with the commands between them")
    # a quit quoted inside an if's branch counts too (field round 21, c28: 'print done' 'quit')
    quits = [command for command in commands if "quit" in (w.strip("\"'") for w in command.split())]
    if any(command.split()[0] != "quit" for command in quits):
        return "may quit"
    return "quits" if quits else None


def _first_not_inert(command: str) -> str | None:
    """The first command word a run's ``every`` may run that can change a contact, None if none:
    inert ones, NULL, quit (it ends the deck) and an if whose every branch is such (its condition
    chooses among them)."""
    try:
        parts = words(command)
    except ScriptError:
        return command
    if not parts or parts[0] in _INERT or parts[0] in ("NULL", "quit"):
        return None
    if (branches := if_branches(parts)) is None:
        return parts[0]
    return next((first for first in map(_first_not_inert, branches) if first is not None), None)


def _where_the_run_left(split: list, placed: set, cmd) -> None:
    """A group, set or delete_atoms after a run: one that picks atoms by where they are (a region,
    a group so picked, an atom-style variable, delete_atoms' overlap or porosity) picks those the
    deck's runs left there, which the engine's pass (its runs skipped, LIGGGHTS' cut to one step)
    never moved: where it changes sizes or types or removes atoms, which it does is not known
    (field test r11: ``set region low diameter 0.02`` after spheres fell gave 0.96186 where LAMMPS
    gives 0.94036). Refused in one line; a group so picked is remembered in ``placed``.

    Examples
    --------
    >>> placed = set()
    >>> _where_the_run_left("group low region bottom".split(), placed, None), placed
    (None, {'low'})
    >>> _where_the_run_left("set group low vx 0.0".split(), placed, None)
    >>> from restitution.dem.deck.stream import Executed
    >>> _where_the_run_left("set group low diameter 0.02".split(), placed, Executed((None, 9), "set"))
    Traceback (most recent call last):
    ...
    restitution.dem.dialect.state.DeckError: line 9 (set): after a run, it picks atoms by where the run left them (group low, picked by where its atoms were after a run), which the audit's pass (its runs skipped) does not know: the sizes and types it leaves are not known; not audited
    """
    if split[0] == "group" and len(split) > 2:
        name, style = split[1], split[2]
        if style in ("delete", "clear"):
            placed.discard(name)
        elif style == "static":
            pass                     # its members frozen where they are now: as placed as before
        elif style in ("region", "variable", "dynamic") or any(g in placed for g in split[3:]):
            placed.add(name)
        else:
            placed.discard(name)     # a group by type or ID holds the atoms of those, wherever
        return None
    why = None
    if split[0] == "set" and len(split) > 3:
        sizing = [(k, v[0]) for k, v in _set_keywords(split) if k in _SIZING_SET and v]
        if not sizing:
            return None
        if split[1] == "region":
            why = f"region {split[2]}"
        elif split[1] == "group" and split[2] in placed:
            why = f"group {split[2]}, picked by where its atoms were after a run"
        elif any(v.startswith("v_") for _, v in sizing):
            why = next(f"{k} {v}, an atom-style variable that may read positions" for k, v in sizing if v.startswith("v_"))
        elif drawn := [k for k, _ in sizing if k in _DRAWN]:
            # field round 28, R22, R25: set group lv1 type/fraction 3 0.5 seed after a run retyped the
            # atom in LAMMPS and not in the pass, or the other way, by the seed
            why = f"{drawn[0]}, {_DRAWN[drawn[0]]}"
    elif split[0] == "delete_atoms" and len(split) > 2:
        if split[1] in ("region", "overlap", "porosity"):
            why = f"delete_atoms {split[1]}"
        elif split[1] == "group" and split[2] in placed:
            why = f"group {split[2]}, picked by where its atoms were after a run"
    if why:
        raise DeckError(place(cmd.loc), cmd.text, f"after a run, it picks atoms by where the run left them ({why}), "
                                                  "which the audit's pass (its runs skipped) does not know: the "
                                                  "sizes and types it leaves are not known; not audited")
    return None


def by_position(commands) -> tuple | None:
    """The first group, set or delete_atoms after a run that picks atoms by where the run left them
    (:func:`_where_the_run_left`, which refuses it in a pass whose runs are skipped), as
    ((file, line), text); None where there is none.

    Examples
    --------
    >>> from restitution.dem.deck.stream import Executed
    >>> cmds = [Executed((None, 3), "run 10", 0), Executed((None, 4), "set region low diameter 0.02")]
    >>> by_position(cmds), by_position(cmds[1:])
    (((None, 4), 'set region low diameter 0.02'), None)
    """
    moved, placed = False, set()
    for cmd in commands:
        try:
            split = words(cmd.text)
        except ScriptError:
            return None                # refused as it is read
        if split and split[0] in ("run", "minimize"):
            moved = True
        elif split and moved and split[0] in ("group", "set", "delete_atoms"):
            try:
                _where_the_run_left(split, placed, cmd)
            except DeckError:
                return cmd.loc, cmd.text
        elif split and split[:1] == ["group"] and len(split) > 2 and split[2] == "dynamic":
            # a dynamic group defined before the runs: its members are where the runs leave them
            # (field round 22, t16: a set of it after a fall set atoms LAMMPS no longer held in it)
            placed.add(split[1])
    return None


def _made_after(deck: Deck, made, what: str, inserting: bool = False) -> None:
    """Atoms of the types ``made`` (None: not known) made by ``what``: a group defined by type
    before them does not hold them (a group holds the atoms present when it is defined; LAMMPS
    measured: an integrator's or a wall's group by type misses a sphere of its type created after
    it), unless it is the group an inserting fix fills with them (``inserting``: ``made`` are an
    inserting fix's); such a group is partial from here on.

    Examples
    --------
    >>> deck = Deck(ntypes=2, groups={"early": {1}, "two": {2}})
    >>> _made_after(deck, {1}, "line 9 (create_atoms 1 single 0 0 0)")
    >>> deck.partial_groups
    {'early': 'line 9 (create_atoms 1 single 0 0 0) made more atoms of its types, which it does not hold'}
    """
    for name, static in deck.groups.items():
        if static is None or name in deck.partial_groups:
            continue
        fills = [f for _, f in deck.filled_groups.get(name, [])]
        if inserting and made in fills:
            continue                     # (as far as the reader can tell) the fix that fills it
        if name in deck.empty_groups:
            static = set(range(1, deck.ntypes + 1))     # made before any atom: every newcomer is outside it
        filled = set().union(*(f for f in fills if f is not None))
        if made is None or (made & static) - filled:
            deck.partial_groups[name] = f"{what} made more atoms of its types, which it does not hold"


def _inserted(deck: Deck) -> None:
    """After a run, the atoms the deck's inserting fixes have made: their types where named."""
    for inserted in deck.inserts:
        if inserted is None:
            deck.present_unknown = True
        else:
            deck.present |= inserted


def set_up_key(deck: Deck) -> str:
    """What the engine reads into its contact forces when it sets a run up (its ``init``): the pair
    style, the coefficients of pairs of two types, the fixes (walls, material properties, what acts
    beside the contact), exclusions and movers; not the atoms' sizes, which it reads from the atoms
    at every step, nor LAMMPS' coefficients of a type with itself, which pair_coeff sets where the
    forces read them (its set-up copies a pair i < j to j > i: measured, below), though a pair of
    it with another type may be mixed from them (:func:`_not_set_up` checks those).

    Parameters
    ----------
    deck : Deck

    Returns
    -------
    str

    Examples
    --------
    >>> set_up_key(Deck(radius={1: 0.5})) == set_up_key(Deck(radius={1: 0.7}))
    True
    >>> a, b = Deck(coeffs={(1, 1): (3, ["hooke", "2000"])}), Deck(coeffs={(1, 1): (9, ["hooke", "5000"])})
    >>> set_up_key(a) == set_up_key(b)
    True
    """
    # the lists' reach decides a meeting only where a cutoff may leave a pair out (_cut); the skin given
    # as the units' default is no change (field round 29, Q28: neighbor 0.001 bin in si refused, Q29
    # nsq: without a cutoff the lists built at the last set-up hold every contact, LAMMPS met the pair)
    skin = deck.skin if deck.skin is not None else DEFAULT_SKIN.get(deck.units or "lj")
    # a like pair's own cutoff is read into the lists' reach at the set-up only (field round 28, Q58:
    # pair_coeff 1 1 given again without its cutoff 0.001 before pre no: LAMMPS kept the short lists
    # and met the pair late, -0.507, where its new law was printed)
    own_cut = sorted((k[0], own_cutoff(w)) for k, (_, w) in deck.coeffs.items() if k[0] == k[1])
    return repr((deck.code, deck.style, deck.model, deck.limit_force, deck.absolute_damping, deck.gran,
                 (skin, deck.neighbor_style, own_cut, deck.cutoff) if _cut(deck) else None,
                 sorted((k, tuple(w)) for k, (_, w) in deck.coeffs.items() if k[0] != k[1]),
                 sorted((k, repr(v)) for k, (_, v) in deck.props.items()),
                 [(w, t) for _, w, t in deck.walls], repr(deck.meshes), [w for _, w in deck.beside],
                 repr(deck.others), repr(deck.idle), repr(deck.granular_of), [w for _, _, w in deck.excludes],
                 sorted((k, repr(v)) for k, v in deck.movers.items())))


def _mixes(deck: Deck, t: int) -> bool:
    """Whether LAMMPS mixes a pair of type ``t`` with another from their own coefficients (no
    pair_coeff sets it) and both types may hold atoms in the run: it mixes them at the run's set-up
    (field round 27, P29: 1 1 made stiffer, then run pre no: the 1 2 pair mixed from it kept the old
    law, 0.413435, not the audit's 0.543252); a mixed pair of a type with no atom and no inserting
    fix to make one never meets (round 28, Q18, Q26: refused though no such pair could happen)."""
    if deck.held is None or None in deck.inserts:
        live = set(range(1, deck.ntypes + 1))
    else:
        live = set(deck.held).union(*deck.inserts)
    return t in live and any((min(t, u), max(t, u)) not in deck.coeffs
                             for u in range(1, deck.ntypes + 1) if u != t and u in live)


def _not_set_up(deck: Deck, words: list, where: str, line: str) -> None:
    """A run with ``pre no`` after its first: the engine does not set it up (LAMMPS' run.cpp: only
    ``pre yes`` or no run yet does), so a contact setting changed since the last set-up acts in part
    or not at all. LAMMPS 22 Jul 2025 measured: ``pair_coeff 1 2`` changed from kn 2000 to 5000
    before ``run N pre no``: 0.4409 (the new kn) where the type-1 sphere is the pair's first atom,
    0.2550 (the old) where it is the second; ``pair_coeff 1 1`` so changed: 0.4409 in either order.
    Refused in one line where such a setting changed; any other run records what its set-up read.
    A run with ``every`` is set up at its first part whatever its pre (run.cpp: ``preflag || iter ==
    0``; field round 36, L04 in LIGGGHTS 3.8.0 and LAMMPS alike: one "Setting up run" for ``run 300
    pre no every 100``; P08 P25 after replicate: the pair met on time)."""
    pre = [] if "every" in words[2:] else [words[k + 1] for k in range(2, len(words) - 1) if words[k] == "pre"]
    key = set_up_key(deck)
    radii = {t: {r for r, _ in sizes} for t, sizes in (deck.held or {}).items()}
    own = {k[0]: tuple(w) for k, (_, w) in deck.coeffs.items() if k[0] == k[1]}
    if pre[-1:] == ["no"] and deck.set_up is not None:
        # field round 34, P75 P76: replicate 1 1 1, then run 3000 pre no: the step count went on and
        # no atom moved (positions and velocities the same after the run, 1 and 2 processes); its
        # pairs and walls are left out (meeting.motion), the runs after it set up again (P79)
        deck.still = deck.replicated
        if deck.still:
            # no atom moves in it: a setting changed since the last set-up meets no pair here, and
            # the next run set up reads it (field round 36, P03 P17: a pair_coeff or a wall fix
            # between replicate and this run; LAMMPS 0.578975 / 0.413435 in the run after)
            return
        if key != deck.set_up:
            raise DeckError(where, line, "pre no after a contact setting changed since the last run: the engine does "
                                         "not set this run up again, so the change acts in part or not at all (LAMMPS "
                                         "measured: a pair_coeff of types 1 2 acts on one order of the pair's atoms "
                                         "only; a neighbor skin is not read); not audited (remove pre no)")
        if mixed := [t for t in sorted(set(own) | set(deck.set_up_own)) if own.get(t) != deck.set_up_own.get(t)
                     and _mixes(deck, t)]:
            if any((t, t) not in deck.set_up_like for t in mixed):
                raise DeckError(where, line, f"pre no after the coefficients of types {mixed[0]} {mixed[0]} were given "
                                             "since the last run, from which LAMMPS mixes a pair of that type with "
                                             "another at a run's set-up: this run is not set up again; not audited "
                                             "(remove pre no)")
            # LAMMPS mixes only at a set-up: the mixed pairs keep the last one's mix, the like pair
            # itself takes its new coefficients (field round 27, P19 P29 P40-P48: refused since,
            # LAMMPS 0.413435, the old mix; measured: 1 1 changed, either order of the atoms alike)
            deck.mixed_own = dict(deck.set_up_like)
        # a grown type's pairs are left out (walls use no list, other pairs are met as set up)
        stale = set(_grown(deck, radii)) | _changed_atoms(deck)
        deck.stale = {**deck.stale, **{t: (where, line) for t in sorted(stale)}}
        # (in any box: on several processes the ghost atoms stand for the other sub-domains' spheres
        # too, field round 34, P47: boundary f f f, balance, pre no, 2 processes: 3.01)
        if deck.reghosted and deck.code != "LIGGGHTS":
            deck.ghosts_stale = deck.reghosted
        return
    deck.set_up, deck.set_up_radii, deck.set_up_own, deck.stale = key, radii, own, {}
    deck.set_up_like, deck.mixed_own = {k: v for k, v in deck.coeffs.items() if k[0] == k[1]}, None
    deck.reghosted = deck.ghosts_stale = deck.replicated = deck.still = ()
    deck.set_up_seen = deck.seen


def _grown(deck: Deck, radii: dict) -> list:
    """The types whose atoms hold a radius (``radii``, type -> radii held now) larger than the
    smallest they held at the last set-up and not one they held then (field round 28, Q01: ``set
    type 2 diameter`` up, then ``run pre no``: LAMMPS and LIGGGHTS kept the lists of the smaller
    spheres and met the pair deep in overlap, 0.841701 for 0.414916, or never; a shrink, Q19, keeps
    them finding every contact). A pair outside the lists at their last build may be missed after
    any growth until the next build, whatever the skin: each atom moved less than half of it. A size
    a pour makes counts too: a sphere set to it is not told from the pour's (field round 29, Q08:
    lv2 set to the 12 mm a pour made, then pre no: LAMMPS 0.843542, the audit had printed 0.414916),
    though the pour's own spheres are in the lists (it has them built again as it inserts)."""
    grown = []
    for t in sorted(radii):
        before, now = deck.set_up_radii.get(t), radii[t]
        # a new radius above the smallest then; or a radius gone whose atoms may have grown to a
        # larger one held already (Q08's lv2, 3 mm to the pour's 6 mm: the sizes held show no new one)
        gone = before - now if before else set()
        if before and (any(r > min(before) for r in now - before) or gone and max(now, default=0) > min(gone)):
            grown.append(t)
    return grown


def _adapted_late(deck: Deck, where: str, line: str) -> None:
    """A run with a fix adapt of atom diameter in force: LAMMPS builds the run's neighbour lists at
    its set-up before the fix sizes the spheres (and the fix grows them as the run goes where its
    diameter varies), so a pair brought within reach by a growth is found late, deep in overlap
    (field round 30, A01: 1.591978 where the audit printed the grown size's 0.370354; A13, A14, A24).
    The types of its group are left out of the run (``deck.stale``) where the adapt's diameter varies,
    or an atom of them grew at the set-up: LAMMPS' pass writes the atoms before it (a shrink, A16,
    and a size kept, A17, are audited). Where the pass has no such account (its runs made for real),
    unless the same adapt of one constant diameter, reset no, was in force at the run before,
    neither it nor a set of diameters ran since, and no atom of them is new or grew since (A12)."""
    adapts = tuple(tuple(w) for _, w in deck.beside if w[3] in ADAPT
                   and any(kind == "atom" and args[:1] == ["diameter"] for kind, args in adapt_parts(w)[0]))
    previous, resized = deck.adapts_before, deck.diameters_set
    deck.adapts_before, deck.diameters_set = adapts, False
    if not adapts or deck.code != "LAMMPS":
        return                  # LIGGGHTS 3.8.0 sized them before its lists (round 30, L14, L15: met in time)
    now, before = getattr(deck.seen, "by_id", None), getattr(deck.seen_before, "by_id", None)
    set_up = getattr(deck.seen, "before", None)
    for w in adapts:
        typed = whole_types(deck, w[2])
        types = typed or set(range(1, deck.ntypes + 1))
        constant = adapted_diameter(deck, list(w)) is not None
        if set_up is not None and now is not None:
            # the radii the set-up's lists saw: no atom of the group grown from them, no growth to come
            held = constant and all(r <= set_up.get(atom, (t, r))[1] for atom, (t, r) in now.items() if t in types)
        else:
            held = (w in previous and not resized and constant
                    and adapt_parts(list(w))[1].get("reset", "no") != "yes"
                    and now is not None and before is not None
                    and all(atom in before and r <= before[atom][1] for atom, (t, r) in now.items() if t in types))
        if not held:
            # a group the audit cannot type is named as the group (field round 39, D12: "type 1" was said
            # of an adapt on an ID group of a type 2 sphere)
            whose = None if typed else f"group {w[2]}"
            deck.stale = {**deck.stale, **{t: (where, line, f"fix {w[1]} adapt", whose) for t in sorted(types)
                                           if t not in deck.stale}}


def _changed_atoms(deck: Deck) -> set:
    """The types now held by an atom that has grown since the last set-up, or changed type where an
    exclusion is in force, read atom by atom (by ID, where the engine gives them): the sizes a type
    holds may stay the same set though one atom grew, to a size another of its type already had,
    while a third kept the old one, or two swapped sizes; a type empty at the set-up has none to
    compare (field round 30, G01, G03, G04: printed at first touch, LAMMPS met the pair late, 0.84).
    The lists built with an exclusion hold no pair of a retyped atom that left it (R09: 0.84) and
    keep one that entered it (R06: met at first touch, where no contact was said).

    Examples
    --------
    >>> from restitution.dem.deck.stream import Snapshot
    >>> before = Snapshot({2: {(0.003, 2500.0), (0.006, 2500.0)}}, by_id={1: (2, 0.003), 2: (2, 0.006), 3: (2, 0.003)})
    >>> now = Snapshot({2: {(0.003, 2500.0), (0.006, 2500.0)}}, by_id={1: (2, 0.006), 2: (2, 0.006), 3: (2, 0.003)})
    >>> _changed_atoms(Deck(seen=now, set_up_seen=before)), _changed_atoms(Deck(seen=before, set_up_seen=now))
    ({2}, set())
    """
    before = getattr(deck.set_up_seen, "by_id", None)
    now = getattr(deck.seen, "by_id", None)
    if before is None or now is None or now == before:
        return set()
    changed = set()
    smallest: dict = {}
    for t, r in before.values():
        smallest[t] = min(r, smallest.get(t, r))
    for atom, (t, r) in now.items():
        held = before.get(atom)
        if held is None:
            # made since (a new ID): larger than a sphere its type held at the set-up, or of a type
            # that held none, it may be missed until the next build (field round 31, SW-G: lv2
            # deleted and made again at a new ID, of the size a victim of its type had: LAMMPS 0.72
            # where the first touch, 0.41, was printed; met in time or not as the deletion left
            # LAMMPS' memory)
            if t not in smallest or r > smallest[t]:
                changed.add(t)
        elif r > held[1] or t != held[0] and deck.excludes:
            changed.add(t)
    return changed


def contact_key(deck: Deck) -> str:
    """What decides the deck's contacts, without the lines it came from: two runs with the same key
    see the same contacts.

    Parameters
    ----------
    deck : Deck

    Returns
    -------
    str

    Examples
    --------
    >>> contact_key(Deck(radius={1: 0.5})) == contact_key(Deck(radius={1: 0.5}, unknown=[(None, 1, "x", "y")]))
    True
    """
    def plain(x):
        if isinstance(x, (set, frozenset)):
            return tuple(sorted(x))
        if isinstance(x, dict):
            return tuple(sorted((k, plain(v)) for k, v in x.items()))
        if isinstance(x, (list, tuple)):
            return tuple(plain(v) for v in x)
        return x
    return repr(plain((deck.code, deck.style, deck.ntypes, deck.radius, deck.density, deck.units, deck.soft,
                       deck.hard, deck.model, deck.limit_force, deck.absolute_damping, deck.gran, deck.atom_style, deck.missing,
                       {k: w for k, (_, w) in deck.coeffs.items()}, {k: v for k, (_, v) in deck.props.items()},
                       # the mix a run with pre no keeps (a later run set up mixes anew: another stage)
                       {k: w for k, (_, w) in (deck.mixed_own or {}).items()},
                       [(w, t) for _, w, t in deck.walls], deck.meshes, deck.empty_groups, deck.filled_groups, deck.partial_groups,
                       deck.pending,
                       set(deck.shapes), deck.sizes, {t: deck.once.get(t, set()) - deck.poured.get(t, set())
                                                      for t in set(deck.sizes) | set(deck.once)}, deck.others, deck.idle, deck.granular_of,
                       [w for _, w in deck.beside],
                       [w for _, _, w in deck.excludes], {k: (g, st) for k, (_, _, g, st) in deck.movers.items()},
                       # a moving fix's group given again between runs holds other atoms from there on
                       {g: deck.groups.get(g, "undefined") for _, _, g, _ in deck.movers.values()},
                       {k: (t, m) for k, (_, t, m) in deck.shaken.items()},
                       bool(deck.bonds), deck.special_lj, sorted(deck.bond_forces), deck.dt_reset[1:],
                       # where a cutoff may leave a pair out, the lists' reach is the run's (field round
                       # 28, N19: a skin made small after the first run was audited with the first's)
                       # and the global cutoff a pair_style granular given again sets (field round 33, C07:
                       # 0.02, then 0.001 before the next run: one stage, audited with 0.02; LAMMPS 8.09)
                       (deck.skin, deck.neighbor_style, deck.periodic, deck.restored_cut, deck.cutoff)
                       if _cut(deck) else None,
                       # how often the lists are rebuilt is each run's own too, read at every step (pre no
                       # or not): a first run's once yes or long delay said nothing of a later run's
                       # contacts (field round 28, N41, N47, N48: no eps, LAMMPS met the pair at first touch)
                       deck.neigh,
                       sorted(deck.stale), deck.ghosts_stale, deck.still,
                       # a velocity given to atoms no fix moves is read by their contacts' damping (field
                       # round 17: a velocity command between two runs of one stage was not seen)
                       sorted({g for _, _, g in deck.velocities}
                              - {g for _, _, g, st in deck.movers.values() if not rigid(st)}))))


def _cut(deck: Deck) -> bool:
    """Whether a pair_style granular cutoff (global, or a pair's own) is set: the only case where the
    neighbour lists' reach (skin, list style, periodic box) decides whether a pair meets."""
    return deck.cutoff is not None or any("cutoff" in words for _, words in deck.coeffs.values())


def _coarsest_dt(stage: Deck, deck: Deck) -> None:
    """A run that sees a stage's contacts at another time step: the stage states the largest of
    its runs' steps, where a contact has the fewest steps and the engine's eps strays furthest."""
    def step(d: Deck):
        return d.dt if d.dt is not None else DEFAULT_DT.get(d.units)
    now, before = step(deck), step(stage)
    if now is not None and (before is None or now > before):
        stage.dt = now


def _stage(deck: Deck, loc, line: str) -> None:
    """A run: the contact settings it sees, kept where they differ from the previous run's."""
    if deck.unmapped:
        raise DeckError(*deck.unmapped)
    if deck.restart_pairs and (kept := deck.restart_pairs[3] - set(deck.coeffs)):
        at, text, style, _ = deck.restart_pairs
        pairs = ", ".join(f"{i} {j}" for i, j in sorted(kept))
        raise DeckError(place(at), text, f"the restart file holds {style} coefficients for types {pairs}, which the "
                                         "deck did not set again before the run at "
                                         f"{place(loc)}: the engine gives no account of them, not audited")
    key = contact_key(deck)
    if deck.stages and deck.stages[-1][2] == key:
        deck.stages[-1][0].append((loc, line))
        _coarsest_dt(deck.stages[-1][1], deck)
        # the lists that find its contacts may be rebuilt otherwise in this run (field round 16, n07:
        # neighbor and neigh_modify changed before a second run with the same contacts)
        seen = (dict(deck.neigh), deck.skin, deck.dt)
        stage = deck.stages[-1][1]
        if seen != (stage.neigh, stage.skin, stage.dt) and seen not in stage.lists_seen:
            stage.lists_seen.append(seen)
        return
    if not deck.code:
        return                           # no pair style yet: no contact to audit in this run
    if deck.may_end:
        raise DeckError(*deck.may_end, "run ... every runs an if that may quit between the run's parts, and a run with "
                                       f"other contact settings follows at {place(loc)}: whether the deck reaches it "
                                       "depends on what the run does, which the engine's pass (its runs skipped or "
                                       "cut to one step) does not show; not audited")
    if len(deck.stages) >= MAX_STAGES:
        raise DeckError(place(loc), line, f"more than {MAX_STAGES} runs with different contact settings: the "
                                          "audit reports each, and stops here")
    stages, deck.stages = deck.stages, []
    # the lists of lines not understood are the whole deck's, shared by every stage
    snap = copy.deepcopy(deck, {id(deck.unknown): deck.unknown, id(deck.ignored): deck.ignored})
    deck.stages = stages
    stages.append(([(loc, line)], snap, key))


def whole_types(deck: Deck, group: str) -> set | None:
    """The types whose every atom group ``group`` holds (a group by type with no atom of its types
    made after it), or None where the audit cannot say.

    Parameters
    ----------
    deck : Deck
    group : str

    Returns
    -------
    set of int, or None

    Examples
    --------
    >>> whole_types(Deck(ntypes=2, groups={"t2": {2}}), "t2"), whole_types(Deck(ntypes=2), "all")
    ({2}, {1, 2})
    >>> whole_types(Deck(ntypes=2, groups={"t2": {2}}, partial_groups={"t2": "line 9"}), "t2") is None
    True
    """
    if group == "all":
        return set(range(1, deck.ntypes + 1))
    static = deck.groups.get(group)
    if not isinstance(static, set) or group in deck.partial_groups or group in deck.empty_groups:
        return None
    return set(static)


def _deleted(deck: Deck, made: dict, group: str, active: dict) -> None:
    """delete_atoms group G after a run: every atom of the types G holds whole (a group by type with
    no atom of its types made after it) is gone, those the pours and deposits made in the runs
    before included, which the engine's pass never held (field round 18, b24, b45: their pairs were
    still reported, though LAMMPS held none); a pour or deposit still in force makes more."""
    static = whole_types(deck, group)
    if static is None:
        return
    for t in static:
        made.pop(t, None)
        if deck.held is not None:
            deck.held.pop(t, None)        # the engine deletes them too: its next run holds none
        if deck.deposits.get(t) not in active:
            deck.deposits.pop(t, None)
            deck.deposited_templates.pop(t, None)
    repour(deck, made, set(static))


def _run_end(deck: Deck, words: list) -> int | None:
    """The step ``run N [upto] ...`` ends at, None where unknown. The engines read N as C's atoi
    does (LIGGGHTS measured: run 0.5 makes no step, run 2.9 two; LAMMPS stops on such an N)."""
    n = re.match(r"[-+]?\d+", words[1]) if len(words) > 1 else None
    if n is None or deck.step is None:
        return None
    return max(int(n.group(0)), deck.step) if "upto" in words[2:] else deck.step + int(n.group(0))


#: LAMMPS' run keywords and the number of values each takes (every: its N, then the commands)
_RUN_KEYWORDS = {"upto": 0, "start": 1, "stop": 1, "pre": 1, "post": 1, "every": None}
#: The words LAMMPS' utils::logical reads as yes or no
_LOGICAL = {"yes", "no", "on", "off", "true", "false", "1", "0"}


def run_refused(words: list, step: int | None, code: str = "LAMMPS") -> str | None:
    """What LAMMPS (22 Jul 2025) says where it stops on a ``run`` command's arguments, None where it
    takes them. Its ``-skiprun`` skips a run before reading them, so the pass never checks them
    (field round 23, R23-R30: ``run 1e2``, ``run -100``, ``every 0``, ``pre maybe``, a ``start``,
    ``stop`` or ``upto`` the step contradicts were audited as runs LAMMPS makes). The step checks
    are made only where the step the runs reach is known (``step`` not None). LIGGGHTS 3.8.0, whose
    pass cuts each run to one step, reads N as C's atoi does and checks N, start, stop and upto alone
    (measured: L50, L51), in messages without the values.

    Parameters
    ----------
    words : list of str
        The run command, as the engine echoed it (its variables substituted).
    step : int or None
        The step the deck's runs have reached before it.
    code : {"LAMMPS", "LIGGGHTS"}
        The engine.

    Returns
    -------
    str or None

    Examples
    --------
    >>> run_refused("run 1e2".split(), 0), run_refused("run 100 every 0 NULL".split(), 0)
    ("Expected integer parameter instead of '1e2'", 'Invalid run every argument: 0')
    >>> run_refused("run 100 upto".split(), 200), run_refused("run 100 start 0 stop 50".split(), 0)
    ('Invalid run command upto value: 100', 'Run command stop value 50 is before end of run at step 100')
    >>> run_refused("run 100 pre no post yes every 50 NULL".split(), None) is None
    True
    >>> run_refused("run 1e2".split(), 0, "LIGGGHTS"), run_refused("run -100".split(), 0, "LIGGGHTS")
    (None, 'Invalid run command N value')
    """
    if len(words) < 2:
        return "Illegal run command"
    if code != "LAMMPS":
        return _liggghts_run_refused(words, step)
    if re.fullmatch(r"[-+]?\d+", words[1]) is None:
        return f"Expected integer parameter instead of '{words[1]}'"
    n, upto, start, stop, k = int(words[1]), False, None, None, 2
    while k < len(words):
        key = words[k]
        if key not in _RUN_KEYWORDS:
            return f"Unknown run keyword: {key}"
        if key == "every":
            if k + 1 >= len(words) or re.fullmatch(r"[-+]?\d+", words[k + 1]) is None:
                return f"Expected integer parameter instead of '{words[k + 1] if k + 1 < len(words) else ''}'"
            if int(words[k + 1]) <= 0:
                return f"Invalid run every argument: {words[k + 1]}"
            break                      # the rest are the commands it runs
        if k + _RUN_KEYWORDS[key] >= len(words):
            return f"Illegal run {key} command: missing argument"
        value = words[k + 1] if _RUN_KEYWORDS[key] else None
        if key == "upto":
            upto = True
        elif key in ("start", "stop"):
            if re.fullmatch(r"[-+]?\d+", value) is None:
                return f"Expected integer parameter instead of '{value}'"
            start, stop = (int(value), stop) if key == "start" else (start, int(value))
        elif value.lower() not in _LOGICAL:
            return f"Expected boolean parameter instead of '{value}'"
        k += 1 + _RUN_KEYWORDS[key]
    if not upto and n < 0:
        return f"Invalid run command N value: {n}"
    if step is None:
        return None
    if upto:
        if n < step:
            return f"Invalid run command upto value: {n}"
        n -= step
    if start is not None and start > step:
        return f"Run command start value {start} is after start of run at step {step}"
    if stop is not None and stop < step + n:
        return f"Run command stop value {stop} is before end of run at step {step + n}"
    return None


def _liggghts_run_refused(words: list, step: int | None) -> str | None:
    """:func:`run_refused` for LIGGGHTS 3.8.0: N, upto, start and stop, N read as atoi reads it."""
    def atoi(word: str) -> int:
        m = re.match(r"\s*[-+]?\d+", word)
        return int(m.group(0)) if m else 0
    n, upto = atoi(words[1]), "upto" in words[2:words.index("every") if "every" in words else None]
    keys = words[2:words.index("every")] if "every" in words else words[2:]
    start = atoi(keys[keys.index("start") + 1]) if "start" in keys[:-1] else None
    stop = atoi(keys[keys.index("stop") + 1]) if "stop" in keys[:-1] else None
    if not upto and n < 0:
        return "Invalid run command N value"
    if step is None:
        return None
    if upto:
        if n < step:
            return "Invalid run command upto value"
        n -= step
    if start is not None and start > step:
        return "Run command start value is after start of run"
    if stop is not None and stop < step + n:
        return "Run command stop value is before end of run"
    return None


def _no_step(deck: Deck, words: list) -> bool:
    """Whether ``run N [upto] ...`` makes no step (``run 0``; ``run N upto`` at step N already), the
    step the runs reach kept in ``deck.step``. Field round 19, C1: b10's run 0 after new coefficients
    was reported as the deck's last stage, where LAMMPS makes no step under them."""
    before, deck.step = deck.step, _run_end(deck, words)
    return deck.step is not None and deck.step <= before


def started(deck: Deck, words: list | None) -> set:
    """The types of the LIGGGHTS insertions waiting for their start step (:attr:`Deck.waiting`) that
    the run ``words`` reaches (all where its end is unknown, or ``words`` is None): from here on they
    are pours (``deck.pours``), which the caller adds to the sizes made.

    Parameters
    ----------
    deck : Deck
        Changed in place.
    words : list of str or None
        The run command; None: the deck's end, where a deck without runs is audited as set up.

    Returns
    -------
    set of int

    Examples
    --------
    >>> deck = Deck(step=0, waiting={"ins": (3000, "insert/pack", {2: {(0.0015, 1500.0)}})})
    >>> started(deck, ["run", "2000"]), started(deck, ["run", "4000"]), deck.pours
    (set(), {2}, {('ins', 2): (2, {(0.0015, 1500.0)})})
    """
    end = None if words is None else _run_end(deck, words)
    types = set()
    for fix, (start, _, made) in list(deck.waiting.items()):
        if end is None or start <= end:
            del deck.waiting[fix]
            for t, sizes in made.items():
                deck.pours[(fix, t)] = (t, sizes)
                types.add(t)
    return types


def _uninserted_templates(deck: Deck) -> None:
    """A LIGGGHTS deck whose sphere templates no insertion draws from (none defined yet): each
    constant-size template sizes its type, as the spheres it describes may be inserted later. Where
    an insertion is defined, only the templates its distribution draws with a weight above 0 make
    spheres (the insertion pours them), and a template it does not draw makes none (field round 19,
    C5: L37, L39 audited sizes LIGGGHTS never made)."""
    if deck.code != "LIGGGHTS" or deck.inserts or deck.held is None or deck.ran:
        return
    for template in deck.sphere_templates.values():
        if template is not None:
            t, size = template
            pour_into(deck, t, {size})


def _moved_in_run(deck: Deck, loc, line: str) -> None:
    """The atoms a fix moved in this run keep the velocity they end it with, which the runs skipped do
    not show: where a later run holds them with no fix, the contact's damping reads it, as it reads a
    velocity command's (meeting.phantom_velocity). Each moving fix's group is kept as a velocity given
    at this run, once."""
    given = {(moved_line, group) for _, moved_line, group in deck.velocities}
    for fix, (_, _, group, style) in deck.movers.items():
        if rigid(style):
            continue
        moved = f"{line} (where fix {fix} ({style}) moved group {group})"
        if (moved, group) not in given:
            deck.velocities = deck.velocities + [(loc, moved, group)]


def _read_data(deck: Deck, words: list, where: str, line: str, read_file) -> None:
    """read_data FILE [nocoeff] [group ID] [add ...] [offset toff ...] [shift ...]: the number of
    types, each type's radius and density where all its atoms share them (where no engine holds
    them), and a data file's Pair Coeffs / PairIJ Coeffs. With ``add`` the file's atoms join those
    held (the deck's number of types kept, LAMMPS stops where the file's exceed it); ``offset``
    moves the file's types (its atoms', coefficients' and labels') up by toff; ``shift`` moves its
    atoms only."""
    name, opts, coeffs, extra = words[1], words[2:], True, 0
    k, add, toff = 0, False, 0
    while k < len(opts):
        if opts[k] == "nocoeff":
            coeffs, k = False, k + 1
        elif opts[k] == "add" and k + 1 < len(opts):
            add, k = True, k + 2           # append, merge or an ID offset: which IDs, not which types
        elif opts[k] == "offset" and k + 5 < len(opts):
            toff = 0 if opts[k + 1] == "0" else atom_type(opts[k + 1], where, line, "offset's type offset")
            k += 6                         # bonds', angles', ... offsets: no contact
        elif opts[k] == "shift" and k + 3 < len(opts):
            k += 4                         # positions: the audit's collision is head-on, wherever
        elif opts[k] == "extra/atom/types" and k + 1 < len(opts):
            # room for types the deck creates later: the file's types keep their numbers
            more = 0 if opts[k + 1] == "0" else atom_type(opts[k + 1], where, line, "extra/atom/types")
            extra, k = extra + more, k + 2
        elif opts[k].startswith("extra/") and k + 1 < len(opts):
            k += 2                             # room for bonds, angles, special neighbours: no contact
        elif opts[k] == "group" and k + 1 < len(opts):
            deck.filled_groups.setdefault(opts[k + 1], []).append((f"read_data {name} adds", None))
            k += 2
        elif opts[k] == "fix" and k + 3 < len(opts):
            k += 4                             # a fix's own section (per-atom values of a property/atom)
        else:
            raise DeckError(where, line, f"read_data option {opts[k]} is not mapped")
    text = fetch(read_file, name, where, line)
    section, hint, per_type = None, "", {}
    for n, raw in enumerate(text.splitlines(), 1):
        if n == 1:
            continue                                   # the title line
        body, _, comment = raw.partition("#")
        body = body.strip()
        if not body:
            continue
        here = f"{name} line {n}"
        if section is None and (m := re.fullmatch(r"(\d+)\s+atom\s+types", body)):
            n_file = atom_type(m.group(1), here, body, "the number of types")
            if not add:
                deck.ntypes = n_file
            elif n_file + toff > deck.ntypes:
                raise DeckError(where, line, f"{name}'s {n_file} atom types from {toff + 1} on exceed the "
                                             f"deck's {deck.ntypes}: LAMMPS stops")
            continue
        if body[0].isalpha():                          # a section's name; data lines start with a number
            section, hint = body, comment.strip()
            if section in ("Pair Coeffs", "PairIJ Coeffs") and coeffs and deck.code != "LAMMPS":
                raise DeckError(here, body, "a data file's pair coefficients before pair_style granular")
            if section in ("Bonds", "Angles", "Dihedrals", "Impropers"):
                deck.bonds = ((name, n), body)
            if section not in {"Atoms", "Pair Coeffs", "PairIJ Coeffs", "Atom Type Labels"} | _DATA_IRRELEVANT:
                deck.unknown.append((name, n, raw.strip(), "data-file section not read"))
            continue
        if section is None:
            continue                                   # header: atoms, box bounds, other counts
        cols = body.split()
        if toff and cols[0].isdigit() and section in ("Atom Type Labels", "Pair Coeffs", "PairIJ Coeffs", "Atoms"):
            # the file's types moved up (an Atoms line's type is its second column)
            at = 1 if section == "Atoms" else 0
            cols[at] = str(int(cols[at]) + toff) if cols[at].isdigit() else cols[at]
            if section == "PairIJ Coeffs" and len(cols) > 1 and cols[1].isdigit():
                cols[1] = str(int(cols[1]) + toff)
        if section == "Atom Type Labels":             # type label, as labelmap atom gives them
            labelmap(deck, ["labelmap", "atom", *cols[:2]], here, body)
        elif section == "Atoms" and deck.held is None:
            style = hint or deck.atom_style
            if style not in _SPHERE_STYLES:
                raise DeckError(here, f"Atoms # {style}", "the reader reads the Atoms section of atom_style "
                                                          "sphere or granular (id type diameter density x y z)")
            if len(cols) < 7:
                raise DeckError(here, body, "an Atoms line of atom_style sphere has at least 7 columns")
            t = atom_type(unlabeled(deck, ["create_atoms", cols[1]], here, body)[1], here, body)
            d, rho = number(cols[2], here, body), number(cols[3], here, body)
            if d <= 0:
                raise DeckError(here, body, "diameter 0 makes a point particle, which has no contact radius")
            per_type.setdefault(t, (set(), set()))
            per_type[t][0].add(d)
            per_type[t][1].add(rho)
        elif section in ("Pair Coeffs", "PairIJ Coeffs") and coeffs:
            i, j = (cols[0], cols[0]) if section == "Pair Coeffs" else (cols[0], cols[1])
            rest = cols[1:] if section == "Pair Coeffs" else cols[2:]
            _pair_coeff(deck, unlabeled(deck, ["pair_coeff", i, j, *rest], here, body), here, body, (name, n))
    deck.present |= set(per_type)
    deck.ntypes += extra
    for t in range(1, deck.ntypes + 1 if deck.held is None else 1):
        if add and t not in per_type:
            continue                                   # the atoms held before keep theirs
        if t not in per_type:
            deck.missing[t] = f"{name} has no atom of type {t}"
            continue
        diameters, densities = per_type[t]
        if len(diameters) == 1:
            deck.radius[t] = 0.5 * diameters.pop()
        else:
            deck.missing[t] = f"{name} gives type {t} diameters from {min(diameters):g} to {max(diameters):g}"
        if len(densities) == 1:
            deck.density[t] = densities.pop()
        else:
            deck.missing[t] = f"{name} gives type {t} densities from {min(densities):g} to {max(densities):g}"


def _set(deck: Deck, words: list, where: str, line: str, loc) -> None:
    absent = []
    if words[1] == "type":
        typed = list(types(words[2], deck.ntypes, where, line))
    elif words[1] == "group" and words[2] == "all":
        # it sets the atoms there now: a type without any keeps no size from it
        typed = sorted(t for t in deck.present if 1 <= t <= deck.ntypes)
        absent = [t for t in range(1, deck.ntypes + 1) if t not in typed]
    else:
        deck.unknown.append((*loc, line, "not understood"))
        return
    rest = words[3:]
    for k in range(0, len(rest) - 1, 2):
        if rest[k] in ("diameter", "density"):
            for t in absent:
                unknown = "the reader does not know whether an" if deck.present_unknown else "no"
                deck.missing.setdefault(t, f"{unknown} atom of type {t} exists when {where} sets group all")
        if rest[k] == "diameter":
            for t in typed:
                deck.radius[t] = 0.5 * number(rest[k + 1], where, line)
        elif rest[k] == "density":
            for t in typed:
                deck.density[t] = number(rest[k + 1], where, line)
        else:
            # mass, density/disc, velocities, ...: how they combine with a diameter is not guessed
            deck.unknown.append((*loc, line, "not understood"))
            return


def _fix(deck: Deck, words: list, where: str, line: str, loc) -> None:
    style = words[3]
    # a fix of the same ID replaces the earlier one where it stood in the engine's list of fixes
    # (LAMMPS' and LIGGGHTS' Modify::add_fix; the style must be the same, else they stop), which
    # orders their forces: a freeze defined again after a gravity still zeroes the forces before
    # the gravity's (LAMMPS measured)
    again = next((k for k, b in enumerate(deck.beside) if b[1][1] == words[1]), None)
    wall_again = next((k for k, w in enumerate(deck.walls) if w[1][1] == words[1]), None)
    _unfix(deck, words[1])
    if style == "move/mesh" and len(words) > 6 and words[4] == "mesh" and (
            words[6] in _SHAKING or words[6] == "linear/variable" and not all(constant_in_time(w, deck.variables) for w in words[7:10])):
        deck.shaken[words[1]] = (loc, line, words[5])
    # a rigid body's spheres move as one body: their types' pairs are named, not audited
    # (meeting.motion), the deck's single spheres audited (field round 13: R03 refused whole)
    if style in MOVERS or rigid(style):
        deck.movers[words[1]] = (loc, line, words[2], style)
        if rigid(style):
            return
    if style.startswith("bond/create"):
        deck.bonds = (loc, line)
    if style in ADAPT:
        # defined anew, it sizes the spheres again at the next set-up (field round 30, A24: 1.210230
        # where the audit printed 0.370354, the fix given again in a loop's include)
        deck.diameters_set = True
        parts, keys = adapt_parts(words)
        if keys.get("reset") == "yes" and any(kind == "atom" and args[:1] != ["charge"] for kind, args in parts) \
                and (deck.code != "LAMMPS" or deck.ran):
            # LAMMPS' pass writes the atoms by a dump at its run's set-up, as the run sees them; the
            # others write them after the run, the sizes put back: the run's own are never read
            raise DeckError(where, line, "fix adapt ... reset yes puts the atoms' sizes back at the end of each run, "
                                         "before the engine's pass writes them: the sizes during the run are not read")
    if style in BESIDE:
        # gravity on every atom accelerates both bodies of a pair alike (beside passes it over
        # there), but pushes a sphere into a wall during a contact
        # each collision it acts on gets its size (deck.beside)
        deck.beside.insert(len(deck.beside) if again is None else again, (loc, list(words)))
        return
    if style == "dt/reset":
        # the time step changes during the runs: the audit's steps per contact are at the deck's
        deck.dt_reset, deck.dt_reset_runs = (loc, line, words[1]), _runs_recorded(deck)
        return
    if style in _INSERTING_FIXES:
        deck.inserting = True
        typed = style in ("pour", "deposit") and len(words) > 5 and words[5].isdigit()
        # with a molecule template the type word is an offset
        made = (set(template_types(deck, words, where, line)) if typed and "mol" in _keywords(words) else
                {int(words[5])} if typed else None)
        # a fix defined again (a loop of 10 000 pours) adds nothing new: kept once
        if made not in deck.inserts:
            deck.inserts.append(made)
        for t in made or ():
            deck.inserters.setdefault(t, {})[words[1]] = style
        if words[2] != "all":
            filled = deck.filled_groups.setdefault(words[2], [])
            if (f"fix {words[1]} ({style}) inserts", made) not in filled:
                filled.append((f"fix {words[1]} ({style}) inserts", made))
    if style in _SHAPED_TEMPLATES:
        typed = [words[k + 1] for k in range(4, len(words) - 1) if words[k] == "atom_type"]
        shaped = [atom_type(typed[0], where, line)] if typed else range(1, deck.ntypes + 1)
        for t in shaped:
            deck.shapes[t] = (loc, line, _SHAPED_TEMPLATES[style])
        return
    least, handler = _FIXES.get(style, (0, None))
    if handler is not None and len(words) >= least:
        handler(deck, words, where, line, loc)
        if wall_again is not None and deck.walls and deck.walls[-1][1][1] == words[1]:
            deck.walls.insert(wall_again, deck.walls.pop())
    elif style == "deform" and _remaps_atoms(words):
        # the atoms are moved with the box every step (remap x, its default): a contact under way is
        # squeezed or stretched (field round 40, B23: x scale 1.05, LAMMPS 0.331 where 0.4149 was printed
        # under "adds no force"; remap v 0.413435)
        deck.unknown.append((*loc, line, "fix deform changes the box as the runs go and moves the atoms with it (remap "
                                         "x): a contact under way is squeezed or stretched, and its eps is none of "
                                         "those printed"))
    elif style in _NO_FORCE:
        deck.unknown.append((*loc, line, f"fix {style} {_NO_FORCE[style]}; it adds no force to a contact" + (
            " (a pair across a periodic face meets its image as the box changes)" if style == "deform" else "")))
    elif style not in _IRRELEVANT_FIXES:
        # a fix the audit does not know may push its atoms (a wall potential, a field): the rows
        # do not include what it does, and say so
        # and to those of every group it names (field round 45, B46: fix spring couple with its second
        # group lv2, only its first was named)
        named = sorted({w for w in words[3:] if w in deck.groups and w != words[2]})
        deck.unknown.append((*loc, line, f"not understood: fix {style} may add forces to its atoms (group "
                                         f"{words[2]}{''.join(f', and group {g} it names' for g in named)}), "
                                         "which the eps printed do not include"))


def _remaps_atoms(words: list) -> bool:
    """Whether a fix deform moves the atoms with the box: its remap keyword x, the default."""
    remap = [words[k + 1] for k in range(4, len(words) - 1) if words[k] == "remap"]
    return (remap[-1:] or ["x"])[0] == "x"


def _runs_recorded(deck: Deck) -> int:
    """How many runs the deck's stages hold so far."""
    return sum(len(stage[0]) for stage in deck.stages)


def _unfix(deck: Deck, fix_id: str) -> None:
    """The fix ``fix_id`` gone (unfixed, or defined again): no longer beside the contact, moving
    atoms or walls, nor a wall a sphere meets."""
    deck.beside = [b for b in deck.beside if b[1][1] != fix_id]
    deck.movers.pop(fix_id, None)
    deck.shaken.pop(fix_id, None)
    deck.pours = {key: made for key, made in deck.pours.items() if key[0] != fix_id}
    # an inserting fix gone inserts no more (field round 19, c30: a pour unfixed before any run was
    # said to insert its type "as the runs go")
    for fixes in deck.inserters.values():
        fixes.pop(fix_id, None)
    deck.waiting.pop(fix_id, None)
    # a fix dt/reset unfixed after a run leaves the time step where it last set it, not at the
    # timestep command's: deck.dt_reset stays until a timestep command (field round 14, r13)
    if deck.dt_reset and deck.dt_reset[2] == fix_id and _runs_recorded(deck) == deck.dt_reset_runs:
        deck.dt_reset = ()
    deck.walls = [w for w in deck.walls if w[1][1] != fix_id]


def _pour(deck: Deck, words: list, where: str, line: str, loc) -> None:
    """fix ID group pour N type seed [keywords]: the diameter and density it gives type t, LAMMPS'
    defaults where the line has no diam or dens (diameter 1, density 1: its documentation, and a
    poured atom in LAMMPS 22 Jul 2025 has radius 0.5 and mass pi/6). A range or poly of several
    diameters (densities) gives the type several sizes (``sizes``: a range sampled with its ends);
    read without the engine, it gives none (the type's entry in ``missing`` says so)."""
    tokens = words[7:]
    if "mol" in tokens:
        _pour_template(deck, words, where, line)
        return
    t = atom_type(words[5], where, line)

    def value(k):
        if k >= len(tokens):
            raise DeckError(where, line, "fix pour's diam or dens keyword is cut short (LAMMPS stops)")
        return number(tokens[k], where, line)
    diameters, densities = {1.0}, {1.0}
    for k, tok in enumerate(tokens):
        if tok == "diam" and k + 1 < len(tokens) and tokens[k + 1] == "one":
            diameters = {value(k + 2)}
        elif tok == "diam" and k + 1 < len(tokens) and tokens[k + 1] == "range":
            diameters = {value(k + 2), value(k + 3)}
        elif tok == "diam" and k + 1 < len(tokens) and tokens[k + 1] == "poly":
            # a diameter of probability 0 is never poured (field round 19, C5: c31 audited 2 mm
            # spheres LAMMPS never made as a size present)
            n = int(value(k + 2))
            diameters = {value(k + 3 + 2 * m) for m in range(n) if value(k + 4 + 2 * m) > 0}
        elif tok == "diam":
            diameters = {value(k + 1), value(k + 2)}          # older LAMMPS: diam lo hi
        elif tok == "dens":
            densities = {value(k + 1), value(k + 2)}
    if deck.ran:
        return                       # the engine made the runs: what it poured is among the atoms held
    deck.sizes.pop(t, None)
    if deck.held is not None:
        _poured(deck, words[1], t, diameters, densities, "poly" in tokens)
        return
    if len(diameters) == 1 and len(densities) == 1:
        deck.radius[t], deck.density[t] = 0.5 * diameters.pop(), densities.pop()
        return
    deck.radius.pop(t, None)       # the hand reader's decks: no range audited
    deck.density.pop(t, None)
    what = "diameters" if len(diameters) > 1 else "densities"
    lo, hi = min(diameters if len(diameters) > 1 else densities), max(diameters if len(diameters) > 1
                                                                        else densities)
    deck.missing[t] = f"fix {words[1]} pours {what} from {lo:g} to {hi:g}"


def _poured(deck: Deck, fix: str, t: int, diameters: set, densities: set, poly: bool) -> None:
    """The sizes pour ``fix`` adds to type t (a range, uniform between its ends, sampled with its
    ends; poly's diameters themselves), with every other source of t's sizes (:func:`pour_into`)."""
    if not poly and len(diameters) > 1:
        lo, hi = min(diameters), max(diameters)
        diameters = {lo + (hi - lo) * k / (_RANGE_SAMPLES - 1) for k in range(_RANGE_SAMPLES)}
    sizes = {(0.5 * d, rho) for d in diameters for rho in (min(densities), max(densities))}
    deck.pours[(fix, t)] = (t, sizes)
    pour_into(deck, t, sizes)


#: molecule command keywords: any of them shifts the template's types or scales its sizes
_MOLECULE_KEYWORDS = frozenset({"offset", "toff", "boff", "aoff", "doff", "ioff", "scale"})


def _template(words: list, where: str, line: str, read_file) -> list | str:
    """molecule ID FILE [FILE ...]: the one sphere of each template as (its type, radius, density),
    or why a pour of them is not audited. LAMMPS gives a template atom the Diameters and Masses
    sections' values; without Masses, density 1 (22 Jul 2025: a poured template atom of diameter 0.3
    has mass pi/6 * 0.3**3); without Diameters it stops at the pour's run (measured). A set of
    several files is poured by molfrac, each template's sphere as its own."""
    if len(words) < 3 or _MOLECULE_KEYWORDS & set(words[3:]):
        return f"molecule {words[1]} has keywords (offset, scale, ...) that the reader does not map"
    spheres = []
    for name in words[2:]:
        atoms = _free_spheres(words[1], fetch(read_file, name, where, line))
        if isinstance(atoms, str):
            return atoms
        spheres.append(atoms)
    return spheres


#: Molecule file header counts of what ties a template's atoms together
_TIES = ("bonds", "angles", "dihedrals", "impropers", "fragments", "body")


def _free_spheres(mol: str, text: str) -> list | str:
    """[(type, radius, density)] of a molecule file's atoms, each poured as a single sphere, or why
    they are not: one atom, or several that nothing ties (no bonds, angles, ...; the pour's rigid and
    shake keywords are refused by :func:`template_types`): LAMMPS pours each as a free sphere (field
    round 46, I03: a two-atom template poured, the deck run to its end, 0.413435 for its pair)."""
    counts, sections, current = {}, {}, None
    for n, raw in enumerate(text.splitlines()):
        body = raw.partition("#")[0].split()
        if n == 0 or not body:
            continue                                   # the title line, blank or comment lines
        if current is None and len(body) == 2 and re.fullmatch(r"\d+", body[0]):
            counts[body[1]] = int(body[0])             # a header: N atoms, N bonds, ...
        elif body[0][0].isalpha():
            current = " ".join(body)
            sections[current] = []
        elif current is not None:
            sections[current].append(body)
    n = counts.get("atoms", 0)
    if n < 1 or n > 1 and any(counts.get(tie, 0) for tie in _TIES):
        return (f"molecule {mol} holds {n or 'no'} atoms{', tied' if n > 1 else ''}: a pour of it inserts clumps of "
                "spheres (rigid or bonded), and the reader audits the head-on contact of two single spheres only")
    if "Diameters" not in sections:
        return f"molecule {mol} has no Diameters section: LAMMPS stops when it pours it"
    if "Types" not in sections:
        return f"molecule {mol} has no Types section"
    try:
        # each section's lines by atom ID
        types, diameters, masses = ({int(row[0]): row[1] for row in sections[key]} if key in sections else None
                                    for key in ("Types", "Diameters", "Masses"))
        out = []
        for atom in range(1, n + 1):
            radius = 0.5 * float(diameters[atom])
            volume = 4.0 / 3.0 * math.pi * radius ** 3
            out.append((int(types[atom]), radius, float(masses[atom]) / volume if masses is not None else 1.0))
    except (IndexError, KeyError, ValueError, ZeroDivisionError):
        return f"molecule {mol}'s Types, Diameters or Masses section does not read as {n} atoms' numbers"
    return out


def _keywords(words: list) -> list:
    """The keywords of a fix pour (after N type seed) or deposit (after N type M seed)."""
    return words[8:] if words[3] == "deposit" else words[7:]


def template_types(deck: Deck, words: list, where: str, line: str) -> dict:
    """{type: {(radius, density)}} that a fix pour or deposit of ``mol TEMPLATE`` makes: each
    template's free spheres (:func:`_free_spheres`), of their own size (diam and dens are ignored: LAMMPS measured),
    of type offset + its type (the fix's type word is that offset, 0 allowed); anything else is
    refused.

    Parameters
    ----------
    deck : Deck
        The deck, with the molecule templates read so far.
    words : list of str
        The fix's words.
    where, line : str
        Where the fix is, and its text, for a refusal.

    Returns
    -------
    dict

    Raises
    ------
    DeckError
        Where the template is not one sphere, is not defined, or the molecules are rigid bodies.

    Examples
    --------
    >>> d = Deck(ntypes=3, templates={"ball": [[(1, 0.003, 2500.0)]]})
    >>> template_types(d, "fix dep all deposit 5 1 200 7 region r mol ball".split(), "line 9", "")
    {2: {(0.003, 2500.0)}}
    >>> template_types(d, "fix p all pour 5 0 7 region r mol ball".split(), "line 9", "")
    {1: {(0.003, 2500.0)}}
    """
    tokens, style = _keywords(words), words[3]
    k = tokens.index("mol")
    made = deck.templates.get(tokens[k + 1]) if k + 1 < len(tokens) else None
    if "rigid" in tokens or "shake" in tokens:
        made = f"fix {style} ... rigid/shake makes each {'poured' if style == 'pour' else 'deposited'} molecule a " \
               "constrained body"
    if made is None:
        made = f"fix {style} ... mol names no molecule template the deck defined"
    if isinstance(made, str):
        raise DeckError(where, line, made)
    offset = int(number(words[5], where, line))
    # molfrac: each molecule's relative probability; one of 0 is never made (field round 19, C5:
    # c36, c37 audited a 3 mm template LAMMPS never made)
    fractions = []
    if "molfrac" in tokens:
        at = tokens.index("molfrac") + 1
        fractions = [number(w, where, line) for w in tokens[at:at + len(made)]]
    if len(fractions) == len(made):
        made = [m for m, f in zip(made, fractions) if f > 0]
    types: dict = {}
    for kind, radius, density in (sphere for template in made for sphere in template):
        types.setdefault(atom_type(str(offset + kind), where, line), set()).add((radius, density))
    return types


def _pour_template(deck: Deck, words: list, where: str, line: str) -> None:
    """fix ID group pour N offset seed ... mol TEMPLATE: the types and sizes of
    :func:`template_types`."""
    poured = template_types(deck, words, where, line)
    if deck.ran:
        return                       # the engine made the runs: what it poured is among the atoms held
    for t, sizes in poured.items():
        deck.sizes.pop(t, None)
        if deck.held is not None:
            deck.pours[(words[1], t)] = (t, sizes)
            pour_into(deck, t, sizes)
        elif len(sizes) == 1:
            deck.radius[t], deck.density[t] = next(iter(sizes))
        else:                          # the hand reader's decks: no range audited
            deck.radius.pop(t, None)
            deck.density.pop(t, None)
            deck.missing[t] = f"fix {words[1]} pours {len(sizes)} templates' sizes into type {t}"


#: Sizes sampled across a pour's range of diameters, its ends included: a law whose eps is not
#: monotonic in size between them would still show its turn to within one sample step
_RANGE_SAMPLES = 9


#: The size LAMMPS gives an atom a fix deposit makes (radius, density): its atom style's defaults
#: (AtomVecSphere: diameter 1, density 1), whatever ``set`` gave the type's atoms before (LAMMPS
#: 22 Jul 2025, atom_style sphere, units si: every deposited atom of a type set to diameter 0.3
#: and density 7000 has radius 0.5 and mass pi/6)
DEPOSITED = (0.5, 1.0)


def _deposit(deck: Deck, words: list, where: str, line: str, loc) -> None:
    """fix ID group deposit N type M seed [keywords]: type t's atoms made as the runs go, with
    LAMMPS' default size (DEPOSITED); a molecule's (mol) from its template, which the reader does
    not read (the type's entry in ``missing`` says so)."""
    if "mol" in words[8:]:
        # its one-sphere templates' sizes, at their offset types (field round 18, b53: the template's
        # 6 mm spheres of type 2 went unseen, and type 2's 4 mm rows were printed alone)
        made = template_types(deck, words, where, line)
        if deck.ran:
            return
        template = _keywords(words)[_keywords(words).index("mol") + 1]
        for t, sizes in made.items():
            deck.deposits[t] = words[1]
            deck.deposited_templates[t] = template
            pour_into(deck, t, sizes)
        return
    t = atom_type(words[5], where, line)
    if deck.ran:
        return                       # the engine made the runs: what it deposited is among the atoms held
    deck.deposits[t] = words[1]
    pour_into(deck, t, {DEPOSITED})


def _resized(deck: Deck, ran: set) -> None:
    """A ``set`` after a run: it may resize the atoms the fixes deposit of ``ran`` made in the runs
    before, which the engine's pass (its runs skipped) never made, so their size is not known:
    each such type in ``missing`` from here on."""
    for t in sorted(ran & set(deck.deposits)):
        deck.deposits[t] = None


#: set keywords that leave an atom's type, radius and mass as they are
_SIZELESS_SET = frozenset({"x", "y", "z", "vx", "vy", "vz", "omega", "angmom", "image", "charge", "temperature",
                           "dipole", "dipole/random", "quat", "quat/random", "theta", "theta/random", "spin",
                           "spin/random", "mol", "property/atom"})
#: set keywords that take more than one value (LIGGGHTS' property/atom: a name and a value)
_SET_VALUES = {"image": 3, "omega": 3, "angmom": 3, "dipole": 3, "quat": 4, "dipole/random": 2, "spin": 4,
               "spin/random": 2, "property/atom": 2, "type/fraction": 3, "type/ratio": 3, "type/subset": 3}


def _set_keywords(words: list) -> list:
    """A set command's keywords with their values, [(keyword, [values])], each keyword taking as many
    values as ``_SET_VALUES`` says (one where it says nothing): reading them two words at a time
    takes a value for a keyword after dipole/random (field round 44, K18: ``set atom 2 dipole/random
    4321 1.0 density 5000`` between runs, its density unseen: 0.4149 printed, LAMMPS 0.376).

    Examples
    --------
    >>> _set_keywords("set atom 2 dipole/random 4321 1.0 vx 0.5".split())
    [('dipole/random', ['4321', '1.0']), ('vx', ['0.5'])]
    """
    out, k = [], 3
    while k < len(words):
        n = _SET_VALUES.get(words[k], 1)
        out.append((words[k], words[k + 1:k + 1 + n]))
        k += 1 + n
    return out


#: set keywords that give some of the atoms chosen another type (the new type their first value)
_RETYPE = ("type", "type/fraction", "type/ratio", "type/subset")
#: set keywords that change an atom's size or type
_SIZING_SET = frozenset({"diameter", "density", "density/disc", "mass", *_RETYPE})
#: What is said of a command that changes the atoms between runs (:func:`_kicks`)
KICKED = ("changes the atoms (their velocities, places, sizes or types, or which atoms there are) or the box "
          "between runs: a contact under way at that step is changed mid-way, and its eps is none of those printed")
#: What is said of a wall fix defined again or removed between runs (:func:`_wall_changed`)
WALL_CHANGED = ("defines again, moves or removes a wall between runs: a contact with it under way at that step is "
                "changed mid-way or never ends, and its eps is none of those printed")
#: set keywords that change an atom's motion, place, size or type
_KICKING_SET = frozenset({"vx", "vy", "vz", "omega", "angmom", "x", "y", "z", "image", "diameter", "density",
                          "density/disc", "mass", *_RETYPE})


def _kicks(split: list) -> str | None:
    """KICKED where the command ``split`` changes the velocities, places, sizes or types of existing
    atoms, or the box (a remap moves them; a periodic image moves without one), else None.

    Examples
    --------
    >>> _kicks(["velocity", "lv2", "set", "0", "0", "-1"]) == _kicks(["set", "type", "1", "type", "2"]) == KICKED
    True
    >>> _kicks(["change_box", "all", "x", "scale", "1.02"]) == KICKED, _kicks(["fix", "f", "all", "nve/sphere"])
    (True, None)
    """
    if split[0] in ("velocity", "displace_atoms", "change_box", "read_dump", "create_atoms", "delete_atoms") or \
            split[0] == "set" and any(k in _KICKING_SET for k, _ in _set_keywords(split)) or \
            split[0] == "read_data" and "add" in split[2:]:
        return KICKED
    return None


#: What is said of a group a fix acts on defined again between runs (:func:`_regrouped`)
REGROUPED = ("defines again a group a fix acts on, between runs: a contact under way at that step meets that fix "
             "(or loses it) mid-way, and its eps is none of those printed")
#: What is said of an exclusion set or lifted between runs (:func:`_unexcluded`)
UNEXCLUDED = ("changes which pairs the engine excludes, between runs: a pair excluded while its spheres came to "
              "overlap is met deep in overlap when the exclusion goes, and its eps is none of those printed")


def _regrouped(split: list, fixes: dict) -> str | None:
    """REGROUPED where ``split`` defines (again) a group that a fix in force (``fixes``: ID -> its words)
    acts on or names among its arguments (field round 42, R09: group gx id 5 before any atom, fix sf gx
    setforce 0 0 0, run 300, group gx id 2: LAMMPS 0.395 where 0.4149 was printed with no word; round
    45, B29: fix sp g3 spring couple gx ..., run 300, group gx clear, group gx id 2: LAMMPS 4.44)."""
    return REGROUPED if split[0] == "group" and len(split) > 2 and any(split[1] in w[2:] for w in fixes.values()) \
        else None


def _unexcluded(split: list) -> str | None:
    """UNEXCLUDED where ``split`` sets or lifts a neigh_modify exclusion (field round 42, N04: exclude
    type 1 2, run 300, exclude none: LAMMPS 0.848 where 0.4149 was printed)."""
    return UNEXCLUDED if split[0] == "neigh_modify" and "exclude" in split[1:] else None


#: The minimizers that set every atom's velocity to zero as they start (damped dynamics; LAMMPS
#: measured: a pair given its velocities, then ``min_style fire``, ``minimize``: left at rest, 0.1 mm
#: apart, field round 46, Z14 Z16; cg keeps them: Z15 met at 0.413435 as without it)
_AT_REST_MINIMIZERS = frozenset({"fire", "quickmin", "fire/old"})
#: What is said of a minimize under one of them (:data:`_AT_REST_MINIMIZERS`)
AT_REST = ("minimize under min_style {style} sets every atom's velocity to zero: the velocities given before it "
           "are gone, so a pair meets only by what moves its spheres after it, and its eps is the one printed "
           "only where it does")
#: What is said of any other command between runs that is not known to leave a contact as it was
#: (:func:`_unlisted`)
BETWEEN_RUNS = ("is run between runs, and the audit does not know it to leave a contact as it was: a contact under "
                "way at that step may be changed mid-way, and its eps may be none of those printed")
#: Commands that leave a contact under way as it was when run between runs: output, control flow,
#: bookkeeping, a new deck (clear and what follows it), and those whose changes another note says
#: (the stage note compares the pair laws and the time step; the notes above name the kicks, walls,
#: groups and exclusions). Anything else is named: the field rounds found one class of changes made
#: mid-contact after another (rounds 39-42, thirteen), so the harmless are listed, not the harmful.
_HARMLESS_BETWEEN = frozenset({
    "print", "echo", "log", "info", "timer", "shell", "python", "thermo", "thermo_style", "thermo_modify",
    "dump", "dump_modify", "undump", "write_dump", "write_data", "write_restart", "write_coeff", "restart",
    "compute", "compute_modify", "uncompute", "label", "jump", "if", "include", "quit", "run",
    "reset_timestep", "run_style", "min_style", "min_modify", "balance", "partition", "package", "suffix",
    "processors", "comm_modify", "comm_style", "communicate", "atom_modify", "neighbor", "neigh_modify",
    "modify_timing", "lattice", "molecule", "replicate", "hard_particles", "soft_particles", "special_bonds",
    "clear", "units", "atom_style", "boundary", "dimension", "newton", "create_box", "read_data", "read_restart",
    "pair_style", "pair_coeff", "pair_modify", "timestep", "group", "set", "velocity", "displace_atoms",
    "change_box", "create_atoms", "delete_atoms", "read_dump",
    # atom IDs given anew: the spheres, their places and velocities stay (field rounds 27-42 re-audited:
    # the rows as before in six decks)
    "reset_atoms", "reset_atom_ids"})
#: Fix styles that change no contact under way where defined or removed between runs: output and
#: averaging, integrators of the spheres (a pair a stage leaves unmoved is said by the stage note),
#: LIGGGHTS' material properties (compared by the stage note) and templates. Not pours and
#: insertions: a sphere poured mid-contact may strike the pair (field round 43, B85: LAMMPS 0.732
#: where 0.4149 was printed), though stopping one (unfix) is harmless; nor gravity, which each stage
#: weighs on a sphere at a wall, but not a contact that spans a change of it.
_HARMLESS_FIX_STYLES = frozenset({
    "ave/time", "ave/atom", "ave/chunk", "ave/correlate", "ave/correlate/long", "ave/histo", "ave/histo/weight",
    "ave/euler", "vector", "print", "store/state", "halt", "balance", "check/timestep/gran", "nve/sphere", "nve",
    "particletemplate/sphere", "particledistribution/discrete", "property/global", "property/atom",
    "heat/gran", "heat/gran/conduction", "heat/flow", "enforce2d"})


def _definition(split: list, deck: Deck) -> list:
    """What a region or variable command defines, to tell a definition given again unchanged: its
    words, and for a region not in box units the lattice in force, whose spacings scale its numbers
    (field round 44, V09: ``lattice sc 0.0074`` between runs, the wall's region given again in its
    own words 9 mm nearer: LAMMPS 0.365 where 0.4149 was printed with no word)."""
    if split[0] == "region" and ("units", "box") not in zip(split, split[1:]):
        return [*split, "|lattice", *(deck.lattice or [])]
    return list(split)


def _unlisted(split: list, fixes: dict, regions: dict, variables: dict, repeated: bool) -> str | None:
    """BETWEEN_RUNS where ``split``, run between runs, is not known to leave a contact under way as
    it was (``fixes``: the fixes in force, ID -> their words; ``regions``: region ID -> its words;
    ``variables``: an equal-style variable's formula by name; ``repeated``: whether it is a region or
    variable defined again as it was last (:func:`_definition`)), else None. A region counts where a fix in force that is not
    harmless names it, or a region such a fix names does (a union's or intersection's parts, however
    deep); a variable where those fixes or regions read it, or a formula they read does,
    however deep; so does a compute, or a harmless fix, whose value (c_ID, f_ID) they read. A fix, a
    region or a variable defined again in its own words changes nothing, nor does deleting a region or
    a variable (its next definition is what is weighed).

    Examples
    --------
    >>> _unlisted("fix v all viscous 0.01".split(), {}, {}, {}, False) == BETWEEN_RUNS
    True
    >>> _unlisted(["print", "x"], {}, {}, {}, False), _unlisted("pair_modify shift yes".split(), {}, {}, {}, False)
    (None, None)
    >>> wall = {"w": "fix w all wall/gran/region granular hooke 1 1 region u".split()}
    >>> parts = {"u": "region u union 2 a b".split(), "b": "region b plane 0 0 0 0 0 1 move NULL NULL v_z".split()}
    >>> [_unlisted(f"region {r} block 0 1 0 1 0 1".split(), wall, parts, {}, False) == BETWEEN_RUNS for r in "uac"]
    [True, True, False]
    >>> _unlisted("variable z equal 2".split(), wall, parts, {}, False) == BETWEEN_RUNS
    True
    >>> _unlisted("variable z equal 2".split(), wall, parts, {}, True)
    >>> _unlisted("variable k equal 2".split(), wall, {}, {}, False), _unlisted(["fix", *wall["w"][1:]], wall, {}, {}, False)
    (None, None)
    >>> pushed = {"f": "fix f all addforce v_fx 0 0".split()}
    >>> _unlisted("variable k equal 2".split(), pushed, {}, {"fx": "2*v_k"}, False) == BETWEEN_RUNS
    True
    >>> _unlisted("compute m all reduce max vx".split(), pushed, {}, {"fx": "c_m/2"}, False) == BETWEEN_RUNS
    True
    >>> _unlisted("compute n all reduce max vx".split(), pushed, {}, {"fx": "c_m/2"}, False)
    >>> _unlisted("fix p all pour 1 1 7 region r".split(), {}, {}, {}, False) == BETWEEN_RUNS
    True
    >>> _unlisted("unfix p".split(), {"p": "fix p all pour 1 1 7 region r".split()}, {}, {}, False)
    """
    def harmful(fix: list) -> bool:
        return fix[3:4] == [] or fix[3] not in _HARMLESS_FIX_STYLES

    def region_words() -> list:
        """The words of the force fixes, of the regions they name and of those regions' parts."""
        fix_words = [w for fix in fixes.values() if harmful(fix) for w in fix[4:]]
        named, todo = set(), [w for w in fix_words if w in regions]
        while todo:
            if (region := todo.pop()) not in named:
                named.add(region)
                todo += [w for w in regions[region][2:] if w in regions]
        return fix_words + [w for r in named for w in regions[r]]

    def read() -> set:
        """The variables, computes and fixes (v_, c_, f_) those words read, and those the variables'
        formulas read, however deep."""
        out, refs = set(), re.findall(r"\b([vcf])_(\w+)", " ".join(region_words()))
        while refs:
            if (ref := refs.pop()) not in out:
                out.add(ref)
                refs += re.findall(r"\b([vcf])_(\w+)", variables.get(ref[1]) or "") if ref[0] == "v" else []
        return out

    # only the commands that may name what a force fix reads pay for finding it
    command = split[0]
    if command in ("region", "variable") and len(split) > 1 and (split[2:3] == ["delete"] or repeated):
        return None
    if command == "pair_modify" and "compute" in split:
        return BETWEEN_RUNS      # compute no: the pair style's forces are not computed at all
    if command in ("compute", "uncompute") and len(split) > 1:
        return BETWEEN_RUNS if ("c", split[1]) in read() else None
    if command == "fix" and len(split) > 3:
        return None if fixes.get(split[1]) == list(split) or not harmful(split) and ("f", split[1]) not in read() \
            else BETWEEN_RUNS
    if command == "unfix" and len(split) > 1:
        stopped = fixes.get(split[1], [])
        return BETWEEN_RUNS if stopped and harmful(stopped) and not _stops_harmlessly(stopped) else None
    if command == "fix_modify":
        return None if _accounting(split) else BETWEEN_RUNS
    if command == "region":
        return BETWEEN_RUNS if len(split) > 1 and split[1] in region_words() else None
    if command in ("variable", "next"):
        names = {("v", name) for name in split[1:2 if command == "variable" else None]}
        return BETWEEN_RUNS if read() & names else None
    if split[:2] == ["kspace_style", "none"]:
        return None
    return None if command in _HARMLESS_BETWEEN else BETWEEN_RUNS


def _stops_harmlessly(fix: list) -> bool:
    """Whether unfixing ``fix`` (its words) leaves a contact under way as it was: a pour or insertion
    stops making spheres, an evaporate deleting them, a dt/reset changing the step (the last one
    stays, which the stage note weighs), a fix adapt without ``reset yes`` (the engine keeps the
    adapted values: field round 39, D20, LAMMPS 0.386313 as audited) and a fix deform that moves no
    atom (``remap none`` or ``v``).

    Examples
    --------
    >>> _stops_harmlessly("fix a all adapt 1 atom diameter v_d".split())
    True
    >>> _stops_harmlessly("fix a all adapt 1 atom diameter v_d reset yes".split())
    False
    >>> _stops_harmlessly("fix d all deform 1 x scale 1.05".split())
    False
    """
    style, keywords = fix[3] if len(fix) > 3 else "", list(zip(fix[4:], fix[5:]))
    return style in _INSERTING_FIXES or style in ("evaporate", "dt/reset") or \
        style == "adapt" and ("reset", "yes") not in keywords or \
        style == "deform" and not _remaps_atoms(fix)


def _mesh_move_changed(split: list, fixes: dict) -> str | None:
    """WALL_CHANGED where ``split`` defines or removes a LIGGGHTS move/mesh fix (``fixes``: the fixes in
    force, ID -> their words)."""
    removed = fixes.get(split[1], []) if split[0] == "unfix" and len(split) > 1 else split
    return WALL_CHANGED if removed[:1] == ["fix"] and removed[3:4] == ["move/mesh"] else None


def _wall_changed(deck: Deck, split: list) -> str | None:
    """WALL_CHANGED where ``split`` defines again (otherwise) or removes a wall fix of the deck, else None."""
    if split[0] not in ("fix", "unfix") or len(split) < 2:
        return None
    walls = [list(w) for _, w, _ in deck.walls if w[1] == split[1]]
    return WALL_CHANGED if walls and (split[0] == "unfix" or list(split) not in walls) else None

#: The set keywords that draw their atoms at random, and what the draw reads that a run changes
#: (LAMMPS' set.cpp: type/fraction seeds each atom's draw with its coordinates; type/ratio and
#: type/subset pick by the atoms' order, which the runs' sorting of atoms changes)
_DRAWN = {"type/fraction": "whose draw LAMMPS seeds with each atom's position",
          "type/ratio": "which draws from the atoms in the order the runs' sorting leaves them",
          "type/subset": "which draws from the atoms in the order the runs' sorting leaves them"}


def set_poured(deck: Deck, made: dict, words: list, loc, text: str) -> bool:
    """A ``set`` after pours ran: the atoms they made in the runs before (``made``, type -> their
    (radius, density), changed in place) exist in LAMMPS, never in the engine's pass (its runs
    skipped), so the reader changes them as LAMMPS does (22 Jul 2025 measured): ``diameter`` keeps
    an atom's mass (its density becomes m / V at the new radius), ``density`` sets the mass of that
    density at the atom's radius, ``mass`` the mass; atoms a pour makes later get its own size again.
    LIGGGHTS' insertions (insert/pack, insert/stream, insert/rate/region of one-sized sphere
    templates) likewise: its engine's pass runs each run for one step, so the atoms inserted after
    that step never exist there. LIGGGHTS 3.8.0 (measured) inserts later atoms at the template's size
    again, but its ``diameter`` keeps the atom's density (the mass becomes that density at the new
    radius) and its ``mass`` leaves that density as it was, for a later diameter to read: a mass is
    not followed. A ``type``, ``type/fraction``, ``type/ratio`` or ``type/subset`` moves some of the
    atoms chosen to another type (which ones, the engine's random draw or a region): those atoms
    may be of the new type, with the sizes the set leaves them, and those not moved keep theirs, so
    both types hold those sizes (22 Jul 2025 measured: 269 poured, ``set type 1 type/fraction 2 0.5
    5678``, 144 left of type 1 and 125 of type 2, every one at the pour's size); ``type`` on every
    atom of a type (``set type T``) moves them all. Where the reader cannot tell which of them a set
    resizes (a region, a group other than all, atom IDs), or how (another keyword: an atom-style
    variable, ...), the type's size is unknown from here on (``resized``, in ``missing`` at each run).

    Parameters
    ----------
    deck : Deck
        Changed in place (``poured``, the types' sizes, ``resized``).
    made : dict
        Type -> {(radius, density)} of the atoms the pours made in the runs so far.
    words : list of str
        The set command's words, as the engine ran it.
    loc : tuple
        (file or None, line number) of the command.
    text : str
        The command, for the reason a size is not known.

    Returns
    -------
    bool
        Whether a type's sizes changed.

    Examples
    --------
    >>> deck = Deck(ntypes=1, held={})
    >>> made = {1: {(0.005, 2500.0)}}
    >>> set_poured(deck, made, "set type 1 diameter 0.006".split(), (None, 9), "")
    True
    >>> [(r, round(rho, 6)) for r, rho in sorted(deck.poured[1])]
    [(0.003, 11574.074074)]
    >>> deck = Deck(ntypes=2, held={})
    >>> set_poured(deck, {1: {(0.005, 2500.0)}}, "set type 1 type/fraction 2 0.5 9".split(), (None, 9), "")
    True
    >>> deck.poured, deck.radius
    ({2: {(0.005, 2500.0)}}, {2: 0.005})
    """
    if len(words) < 3:
        return False
    try:
        words = unlabeled(deck, words, place(loc), text)
    except DeckError:
        return False                  # LAMMPS stops on a label it does not know: its own refusal
    if words[1] == "type":
        try:
            targets = [t for t in types(words[2], deck.ntypes, place(loc), text) if made.get(t)]
        except DeckError:
            return False              # LAMMPS stops on the range: its own refusal
        exact = True
    elif words[1] == "group" and (whole := whole_types(deck, words[2])) is not None:
        # a group by type that holds every atom of its types sets them as set type does (field
        # round 18, b46: set group t2 after a pour was refused)
        targets, exact = [t for t in sorted(whole) if made.get(t)], True
    else:
        targets = [t for t, sizes in made.items() if sizes]
        exact = False
    changed, liggghts = False, deck.code == "LIGGGHTS"
    fixes, cut = ("insertions", "each run cut to one step") if liggghts else ("pours", "its runs skipped")
    # the atoms moved to another type, added once every target is read: new type -> their sizes
    moved: dict = {}
    retyped: set = set()
    for t in targets:
        # each size made -> what the set makes of it (a size only a pour that may have finished
        # gave stays such a size after the set)
        image, why, k, to, gone = {size: size for size in made[t]}, None, 3, set(), False
        while k < len(words) and not why:
            key, n = words[k], _SET_VALUES.get(words[k], 1)
            value, k = words[k + 1:k + 1 + n], k + 1 + n
            if len(value) < n:
                why = "its keywords do not pair with values"
            elif key in _SIZELESS_SET:
                continue
            elif key in _RETYPE:
                new = deck.labels.get(value[0], value[0])
                if not (str(new).isdigit() and 1 <= int(new) <= deck.ntypes):
                    why = f"set ... {key} {value[0]}: not a type of the deck's"
                else:
                    to.add(int(new))
                    # the plain keyword on every atom of the type moves them all
                    gone = gone or (key == "type" and exact and words[1] == "type" and int(new) != t)
            elif not exact:
                why = f"set {words[1]} {words[2]}: the reader does not know which"
            elif key not in ("diameter", "density", "mass"):
                why = f"set ... {key} changes them in a way the reader does not map"
            elif (x := _float(value[0])) is None:
                why = f"set ... {key} {value[0]}: its value per atom is not read"
            elif key == "diameter" and liggghts:
                image = {o: (0.5 * x, rho) for o, (_, rho) in image.items()}
            elif key == "diameter":
                image = {o: (0.5 * x, rho * (r / (0.5 * x)) ** 3) for o, (r, rho) in image.items()}
            elif key == "density":
                image = {o: (r, x) for o, (r, _) in image.items()}
            elif liggghts:
                why = ("set ... mass: LIGGGHTS keeps the atom's density beside its mass, and a later diameter or "
                       "insertion reads that density, which the reader does not follow")
            else:
                image = {o: (r, x / (4.0 / 3.0 * math.pi * r ** 3)) for o, (r, _) in image.items()}
        if why:
            # and those it moves to another type, wherever in the set its type keyword is
            for u in {t} | _retype_to(deck, words):
                deck.resized[u] = (f"{place(loc)} ({' '.join(text.split())}) changes the atoms the {fixes} made of "
                                   f"type {t} in the runs before, which the engine's pass ({cut}) never made: {why}, "
                                   "so their size is not known")
            changed = True
            continue
        image = {o: (r, float(f"{rho:.12g}")) for o, (r, rho) in image.items()}
        sizes = set(image.values())
        for u in to:
            moved.setdefault(u, set()).update(sizes)
        if gone:
            made[t] = set()
            retyped.add(t)
        elif sizes != made[t]:
            made[t] = sizes
            # those made, and those the pours in force make from here on at their own size
            deck.poured[t] = sizes.union(*(s for u, s in deck.pours.values() if u == t))
            # a pour that has made all its atoms makes no more: its own size is there only if not,
            # and so is what this set makes of a size that was there only if not
            before = deck.pending.get(t, {})
            pending = {image[o]: fixes for o, fixes in before.items() if o in image}
            pending.update({size: [(key[0], place(loc))] for key, (u, ours) in deck.pours.items() if u == t
                            for size in ours if size not in sizes})
            deck.pending[t] = pending
            pour_into(deck, t, set())       # the type's sizes anew (a type no atom of holds in the pass)
            changed = True
    for u, sizes in moved.items():
        if not sizes <= made.get(u, set()):
            made[u] = made.get(u, set()) | sizes
            retyped.add(u)
    repour(deck, made, retyped)
    return changed or bool(retyped)


def _retype_to(deck: Deck, words: list) -> set:
    """The types a set's type keywords (``_RETYPE``) move atoms to, as far as its words pair with values."""
    out, k = set(), 3
    while k < len(words):
        key, n = words[k], _SET_VALUES.get(words[k], 1)
        if key in _RETYPE and k + 1 < len(words):
            new = str(deck.labels.get(words[k + 1], words[k + 1]))
            if new.isdigit() and 1 <= int(new) <= deck.ntypes:
                out.add(int(new))
        k += 1 + n
    return out


def repour(deck: Deck, made: dict, changed: set) -> None:
    """The sizes of each type in ``changed`` anew: those of the atoms the pours made in the runs so far
    (``made``) and those the pours in force make from here on (and a fix deposit's). A pour
    unfixed (or defined anew) before it ran made none, and one unfixed after a ``set`` resized
    what it made adds its own size no more (LAMMPS measured: pour, run, set type 1 diameter 0.006,
    unfix, run: every atom of the type has radius 0.003); a type left with none has no particle
    the engine's pass does not hold.

    Parameters
    ----------
    deck : Deck
        Changed in place (``poured``, the types' sizes).
    made : dict
        Type -> {(radius, density)} of the atoms the pours made in the runs so far.
    changed : set of int
        The types whose pours (or the atoms they made) changed.

    Examples
    --------
    >>> deck = Deck(ntypes=1, held={}, poured={1: {(0.005, 2500.0)}}, radius={1: 0.005}, density={1: 2500.0})
    >>> repour(deck, {}, {1})
    >>> deck.poured, deck.radius
    ({}, {})
    """
    for t in sorted(changed):
        now = set(made.get(t, ())).union(*(s for u, s in deck.pours.values() if u == t))
        if t in deck.pending:
            # a size a pour that may have finished gave stays in doubt where it may have been made
            deck.pending[t] = {size: fixes for size, fixes in deck.pending[t].items() if size in now}
        if t in deck.deposits:
            now.add(DEPOSITED)
        if now == deck.poured.get(t):
            continue
        if now or t in (deck.held or {}):
            deck.poured[t] = now
            pour_into(deck, t, set())
            continue
        deck.poured.pop(t, None)          # (a clear has already dropped it)
        for known in (deck.radius, deck.density, deck.sizes, deck.sampled):
            known.pop(t, None)


def adapt_poured(deck: Deck, made: dict, loc, text: str, during: bool) -> set:
    """The atoms the pours made (``made``, changed in place) resized by the fix adapts in force
    that give their group one constant diameter (LAMMPS 22 Jul 2025 measured, adapt 0 on group
    all beside a pour: after the first run the atom created has the adapted radius, the 269 poured
    the pour's; at the second run's set-up all 270 the adapted one, the 131 poured in it the pour's;
    adapt 10: every atom the adapted one after each run). At a run's set-up (``during`` False) every
    such adapt resizes them; during the run (True) those whose N is not 0. An adapt's ``mass yes``
    (its default) keeps the density, ``mass no`` the mass. Where the reader cannot tell which
    poured atoms its group holds, the deck is refused.

    Parameters
    ----------
    deck : Deck
        The deck as read so far (its fixes in force, groups and variables).
    made : dict
        Type -> {(radius, density)} of the atoms the pours made in the runs so far.
    loc : tuple
        (file or None, line number) of the run.
    text : str
        The run.

    Returns
    -------
    set of int
        The types whose poured atoms it resized.

    Raises
    ------
    DeckError
        Where the adapt's group may hold poured atoms the reader cannot type.

    Examples
    --------
    >>> deck = Deck(ntypes=1, code="LAMMPS", variables={"d": "0.006"},
    ...             beside=[((None, 5), "fix a all adapt 0 atom diameter v_d".split())])
    >>> made = {1: {(0.005, 2500.0)}}
    >>> adapt_poured(deck, made, (None, 6), "run 10", during=False), made
    ({1}, {1: {(0.003, 2500.0)}})
    """
    done: set = set()
    if deck.code != "LAMMPS" or not any(made.values()):
        return done
    for where, words in deck.beside:
        if words[3] not in ADAPT or (diameter := adapted_diameter(deck, words)) is None:
            continue
        if during and words[4] == "0":
            continue
        group = words[2]
        if group == "all":
            resized = [t for t in made if made[t]]
        else:
            fillers = [filled for _, filled in deck.filled_groups.get(group, [])]
            typed = deck.groups.get(group, set())
            if None in fillers or typed is None or typed & {t for t in made if made[t]}:
                raise DeckError(place(where), " ".join(words), f"which atoms a pour made group {group} holds, which "
                                                               f"this adapt resizes at the run at {place(loc)} "
                                                               f"({text}), the reader does not know: not audited")
            resized = sorted(set().union(*fillers) & {t for t in made if made[t]})
        keep_mass = adapt_parts(words)[1].get("mass", "yes") == "no"
        r = 0.5 * diameter
        for t in resized:
            made[t] = {(r, float(f"{rho * (a / r) ** 3 if keep_mass else rho:.12g}")) for a, rho in made[t]}
        done.update(resized)
    return done


def _variable(deck: Deck, words: list) -> None:
    """variable NAME STYLE ...: an equal-style variable's formula (defined again, the new one: LAMMPS
    replaces it), None for other styles; delete forgets it."""
    if words[2] == "delete":
        deck.variables.pop(words[1], None)
    elif words[2] == "getenv" and len(words) > 3:
        deck.environment[words[3]] = deck.putenv.get(words[3], os.environ.get(words[3], ""))
        deck.variables[words[1]] = None
    else:
        deck.variables[words[1]] = " ".join(words[3:]) if words[2] == "equal" else None


def _float(token: str) -> float | None:
    """The number a token reads as, None where it does not (a variable, a word)."""
    try:
        return float(token)
    except ValueError:
        return None


def _sampled(sizes: list) -> list:
    """At most about _RANGE_SAMPLES + 6 of a type's held sizes, sorted by radius: evenly spaced in
    that order, the two smallest and two largest radii and the two lightest and two densest among
    them (pairing every size of a type with hundreds of sizes with every other costs minutes where
    the eps of a few spread over them tells the range; a size one sphere alone holds meets only
    others, so the next one to each end is kept too)."""
    if len(sizes) <= _RANGE_SAMPLES:
        return sizes
    picks = {sizes[round(k * (len(sizes) - 1) / (_RANGE_SAMPLES - 1))] for k in range(_RANGE_SAMPLES)}
    by_density = sorted(sizes, key=lambda s: s[1])
    picks |= {*sizes[:2], *sizes[-2:], *by_density[:2], *by_density[-2:]}
    return sorted(picks)


def _wall(deck: Deck, words: list, where: str, line: str, loc) -> None:
    """fix wall/gran or wall/gran/region: kept with the types its group holds now; its dialect
    reads it when audited."""
    group = words[2]
    deck.walls.append((loc, words, "all" if group == "all" else deck.groups.get(group, "undefined")))


#: fix style -> (its least number of words, what it does to the deck): the engines' alike, then each
#: dialect's own; shorter, not understood
_FIXES = {"pour": (7, _pour), "deposit": (8, _deposit), "wall/gran": (4, _wall), "wall/gran/region": (4, _wall),
          **{style: fix for dialect in DIALECTS.values() for style, fix in dialect.FIXES.items()}}


def _group(deck: Deck, words: list) -> None:
    """group ID type T ... (T, A:B or <> A B): the types a wall acts on. Groups of other styles
    (region, id, molecule, ...) have no types the reader can know: None. A second type line adds."""
    name, style, args = words[1], words[2], words[3:]
    deck.disjoint = {pair for pair in deck.disjoint if name not in pair}
    if style == "subtract" and len(args) > 1 and name not in deck.groups:
        deck.disjoint |= {frozenset((name, other)) for other in args[1:] if other != name}
    if style in ("delete", "clear"):
        deck.groups.pop(name, None)
        deck.empty_groups.discard(name)
        deck.partial_groups.pop(name, None)
        return
    held = None
    if style == "type" and args:
        if args[0] == "<>" and len(args) == 3 and all(a.isdigit() for a in args[1:]):
            held = set(range(int(args[1]), int(args[2]) + 1))
        elif all(re.fullmatch(r"\d+(:\d+)?", a) for a in args):
            held = set()
            for a in args:
                lo, _, hi = a.partition(":")
                held |= set(range(int(lo), int(hi or lo) + 1))
    if held is None and not deck.atoms and style != "dynamic" and name not in deck.groups:
        # any static group made before any atom exists holds none (a region's, the usual LIGGGHTS
        # nve_group that an insertion then fills): its members are those inserted into it by name
        held = set()
    if held is not None and deck.atoms:
        deck.empty_groups.discard(name)
    elif held is not None and name not in deck.groups:
        deck.empty_groups.add(name)
    old = deck.groups.get(name, set())
    if held is not None and old is not None and old <= held and deck.atoms:
        deck.partial_groups.pop(name, None)     # every atom of its types is a member again
    deck.groups[name] = None if held is None or old is None else old | held
