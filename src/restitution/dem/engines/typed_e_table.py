"""The e a user types into a code against the eps the code really gives, for every registered
engine whose damping is set from a typed e (rows from each engine's ``typed_e``).

It reads the engine registry, so it lives beside it, above the engines: restitution.dem.typed_e holds
the formulas the engines themselves share and cannot import the registry without a cycle.
"""

from __future__ import annotations

from . import ENGINES
from ..extrapolate import richardson

__all__ = ["typed_e_table", "typed_e_codes", "typed_e_engine_cases", "typed_e_engine_results", "TYPED_E_CODES",
           "TYPED_E_ENGINES", "TYPED_E_ENGINE_ES", "TYPED_E_ENGINE_RTOL", "TYPED_E_ENGINE_REFINEMENTS"]


def typed_e_codes() -> dict:
    """The typed-e rows of every registered engine, in registry order.

    Each row gives eps as a function of e alone (D2 / sqrt(D1) depends on e only and Omega =
    D1 / D2^2 for these exponents), whatever the particles and the speed.

    Returns
    -------
    dict
        {row label: (function of a typed e -> Contact, the engine version that confirms it)}.

    Examples
    --------
    >>> rows = typed_e_codes()
    >>> "Yade ViscElMat (tc, en)" in rows, rows["Yade ViscElMat (tc, en)"][1]
    (True, 'Yade 2023.02a')
    """
    return {row: (law, engine.version) for engine in ENGINES.values() for row, law in engine.typed_e.items()}


#: The codes whose damping is set from a typed restitution coefficient e (the shipped engines'
#: rows), and the engine (and the version run) that confirms each: the engine tests run every row
#: in its engine at each e of TYPED_E_ENGINE_ES and demand the row's eps to TYPED_E_ENGINE_RTOL
#: (relative, engine extrapolated to dt = 0). The manuscript's table prints these three, so the
#: claim it makes is the one the tests enforce.
TYPED_E_CODES = {row: law for row, (law, _) in typed_e_codes().items()}
TYPED_E_ENGINES = {row: version for row, (_, version) in typed_e_codes().items()}
#: Both ends of the table's range and its middle: the clamp matters most at small e, Thornton's fit
#: fails near e = 1.
TYPED_E_ENGINE_ES = (0.1, 0.5, 0.99)
TYPED_E_ENGINE_RTOL = 1e-6
#: Each confirming run is made at t_c / (typed_e_steps k) for these k, then extrapolated to dt = 0.
TYPED_E_ENGINE_REFINEMENTS = (1, 2, 4)


def typed_e_table(es, codes=None) -> list[dict]:
    """For each typed e, the eps each code really gives.

    Parameters
    ----------
    es : iterable of float
        The typed restitution coefficients, each in (0, 1).
    codes : list of str, optional
        The rows to give (keys of :data:`TYPED_E_CODES`); every registered one by default.

    Returns
    -------
    list of dict
        One {"e": e, row: eps, ...} per e, eps to relative accuracy 1e-10 (the library's reference
        integration at rtol 1e-12).

    Raises
    ------
    KeyError
        For a row no registered engine has.
    restitution.core.errors.ParameterError
        For an e outside (0, 1).

    Examples
    --------
    >>> row = typed_e_table([0.5], codes=["LIGGGHTS hertz, limitForce off (default)", "Yade ViscElMat (tc, en)"])[0]
    >>> round(row["LIGGGHTS hertz, limitForce off (default)"], 6), round(row["Yade ViscElMat (tc, en)"], 4)
    (0.5, 0.5503)
    """
    laws = {row: law for row, (law, _) in typed_e_codes().items()}
    codes = list(laws) if codes is None else codes
    return [{"e": float(e), **{c: laws[c](float(e)).eps(1.0) for c in codes}} for e in es]


def typed_e_engine_cases(engine: str, pair, material: dict, g: float, es=TYPED_E_ENGINE_ES) -> list[dict]:
    """The runs that confirm an engine's typed-e rows in the engine itself, not yet run.

    For each row of the engine and each e, three runs at t_c / n for n = ``typed_e_steps`` times
    each of :data:`TYPED_E_ENGINE_REFINEMENTS`, long enough for the spheres to part.

    Parameters
    ----------
    engine : str
        A key of the engine registry whose engine has typed-e rows.
    pair : restitution.dem.pair.Pair
        The two spheres (the rows' eps does not depend on them).
    material : dict
        E and nu, where a row's stiffness reads them.
    g : float
        The impact speed (the rows' eps does not depend on it).
    es : iterable of float
        The typed e of the runs.

    Returns
    -------
    list of dict
        One {"row", "e", "eps" (the table's), "eps_setting" (the library's for the engine setting the
        runs are given), "gamma", "steps" (n of each run), "runs"} per row and e, in the engine's row
        order; ``runs`` holds the three (setting, g, dt, t_run) its runner's
        ``eps_runs(pair, runs)`` takes.

    Examples
    --------
    >>> from restitution.dem.pair import Pair
    >>> cases = typed_e_engine_cases("yade", Pair.spheres(1e-3, 1.5e-3, 2500.0, 7800.0), {"E": 5e7, "nu": 0.3}, 0.1)
    >>> len(cases), cases[0]["row"], cases[0]["e"], round(cases[0]["eps"], 4), cases[0]["steps"]
    (6, 'Yade ViscElMat (tc, en)', 0.1, 0.2527, [2000, 4000, 8000])
    """
    entry = ENGINES[engine]
    steps = [entry.typed_e_steps * k for k in TYPED_E_ENGINE_REFINEMENTS]
    cases = []
    for row in entry.typed_e:
        for e, line in zip(es, typed_e_table(es, [row])):
            contact, setting = entry.typed_e_case(row, e, pair, material)
            t_c = contact.contact_time(g)
            # under the force rule the spheres still overlap at t_c and coast apart at eps g (the
            # clamped force is zero): strongly damped, that takes longer than the half contact time added
            col = contact.collision(g)
            coast = col.x_c * float(contact.material.length_scale(g)) / (col.eps * g)
            cases.append({"row": row, "e": float(e), "eps": line[row], "eps_setting": col.eps, "gamma": contact.gamma,
                          "steps": steps,
                          "runs": [(setting, g, t_c / n, 1.5 * t_c + 2.0 * coast) for n in steps]})
    return cases


def typed_e_engine_results(cases: list[dict], eps: list[float]) -> list[dict]:
    """Each case's engine eps, extrapolated to dt = 0, against the table's.

    Parameters
    ----------
    cases : list of dict
        From :func:`typed_e_engine_cases`.
    eps : list of float
        The engine's eps of every run of every case, in order (what ``eps_runs`` returned).

    Returns
    -------
    list of dict
        One {"row", "e", "eps_table", "n" (steps per contact of the coarsest run), "eps_dt1",
        "eps_dt2", "eps_dt4" (the engine's at t_c / n, t_c / 2n, t_c / 4n), "eps_engine" (extrapolated
        to dt = 0), "relative_deviation"} per case.

    Raises
    ------
    ValueError
        When ``eps`` does not hold one number per run.

    Examples
    --------
    >>> case = {"row": "r", "e": 0.5, "eps": 0.5, "gamma": 0, "steps": [10, 20, 40], "runs": [None] * 3}
    >>> res = typed_e_engine_results([case], [0.5041, 0.502025, 0.50100625])[0]   # 0.5 + 4e-3 h + 1e-4 h^2
    >>> round(res["eps_engine"], 12), res["eps_dt1"]
    (0.5, 0.5041)
    """
    if len(eps) != sum(len(c["runs"]) for c in cases):
        raise ValueError(f"{len(eps)} eps for {sum(len(c['runs']) for c in cases)} runs")
    out, i = [], 0
    for c in cases:
        runs = eps[i: i + len(c["runs"])]
        i += len(c["runs"])
        got = richardson(*runs, c["gamma"])
        out.append({"row": c["row"], "e": c["e"], "eps_table": c["eps"], "n": c["steps"][0],
                    **{f"eps_dt{n // c['steps'][0]}": x for n, x in zip(c["steps"], runs)}, "eps_engine": got,
                    "relative_deviation": got / c["eps"] - 1.0})
    return out
