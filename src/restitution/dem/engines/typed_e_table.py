"""The e a user types into a code against the eps the code really gives, for every registered
engine whose damping is set from a typed e (rows from each engine's ``typed_e``).

It reads the engine registry, so it lives beside it, above the engines: restitution.dem.typed_e holds
the formulas the engines themselves share and cannot import the registry without a cycle.
"""

from __future__ import annotations

from . import ENGINES

__all__ = ["typed_e_table", "typed_e_codes", "TYPED_E_CODES", "TYPED_E_ENGINES", "TYPED_E_ENGINE_ES",
           "TYPED_E_ENGINE_RTOL"]


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
