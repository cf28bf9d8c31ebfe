"""The ``restitution`` subcommands of the model itself: ``series``, ``collide``, ``eps`` and
``calibrate``."""

from __future__ import annotations

import argparse
import json
import math

from ..core.errors import ParameterError
from ..core.exponents import number_argument
from .common import Progress, UsageError, add_end, add_exponents, positive_int, write_json

__all__ = ["add_physics_subcommands", "add_eps_subcommand", "run_eps", "run_series", "run_collide", "run_calibrate"]


def add_physics_subcommands(sub) -> None:
    """Add ``series``, ``collide``, ``eps`` and ``calibrate`` to the subparsers ``sub``, in that order."""
    s = sub.add_parser("series", help="exact perturbation series x_n(tau) of the scaled equation")
    add_exponents(s)
    s.add_argument("--omega-order", type=positive_int, default=4, help="highest power of Omega (default 4)")
    s.add_argument("--max-power", default="11", help="highest power of tau kept, a rational >= 1 (default 11)")
    s.add_argument("--inverse", action="store_true", help="the inverse collision x'' + Omega x^a - x^g x' = 0")
    s.add_argument("--json", action="store_true", help="machine-readable output")

    c = sub.add_parser("collide", help="integrate one collision: eps, tau_b, x_b, tau_c, x_c")
    add_exponents(c)
    c.add_argument("--omega", type=number_argument, help="scaled parameter Omega > 0")
    c.add_argument("--D1", type=number_argument, help="elastic constant D1 > 0 (with --D2 and --g)")
    c.add_argument("--D2", type=number_argument, help="dissipative constant D2 > 0")
    c.add_argument("--g", type=number_argument, help="impact speed g > 0")
    c.add_argument("--rtol", type=number_argument, default=None,
                   help="relative tolerance of methods reference and integrator (default 1e-12)")
    c.add_argument("--method", default="reference",
                   help="reference (scipy, default), integrator (compiled; formerly fast), highprec (mpmath) "
                        "or exact-family, alias closed-form (alpha = 2 gamma + 1: the linear dashpot at "
                        "(gamma+1) Omega, exact)")
    c.add_argument("--digits", type=int, default=None, help="digits of --method highprec (default 30)")
    add_end(c)
    c.add_argument("--json", action="store_true", help="machine-readable output")

    add_eps_subcommand(sub)

    k = sub.add_parser("calibrate", help="the damping D2 that gives a target eps at an impact speed",
                       description="D2 of delta'' + D1 delta^alpha + D2 delta^gamma delta' = 0 with eps(g) = "
                                   "--eps; several --g/--eps pairs: least squares, residual reported.")
    add_exponents(k)
    k.add_argument("--D1", type=number_argument, required=True, help="elastic constant D1 > 0")
    k.add_argument("--eps", type=number_argument, nargs="+", required=True, metavar="E", help="target eps in (0, 1)")
    k.add_argument("--g", type=number_argument, nargs="+", required=True, metavar="V", help="impact speed(s) > 0")
    add_end(k)
    k.add_argument("--json", action="store_true", help="machine-readable output")



def run_calibrate(args, out) -> None:
    from ..dem.calibrate import calibrate
    one = len(args.eps) == 1 and len(args.g) == 1
    res = calibrate(args.alpha, args.gamma, D1=args.D1, eps=args.eps[0] if one else args.eps,
                    g=args.g[0] if one else args.g, end=args.end).as_dict()
    if args.json:
        write_json(res, out)
        return
    for key, value in res.items():
        out.write(f"{key:>8}  {value:.12g}\n" if isinstance(value, float) else f"{key:>8}  {value}\n")


def add_eps_subcommand(subparsers) -> argparse.ArgumentParser:
    p = subparsers.add_parser(
        "eps", help="coefficient of restitution to a tolerance (picks the cheapest adequate method)",
        description="eps for Omega values or impact speeds, to a relative tolerance; says which method "
                    "was used and its error bound.")
    p.add_argument("--alpha", required=True, help="elastic exponent, a rational > 0 such as 3/2")
    p.add_argument("--gamma", required=True, help="dissipative exponent, a rational >= 0 such as 1")
    p.add_argument("--omega", type=number_argument, nargs="+", metavar="W", help="scaled parameter(s) Omega > 0")
    p.add_argument("--D1", type=number_argument, help="elastic constant D1 > 0 (with --D2 and --g)")
    p.add_argument("--D2", type=number_argument, help="dissipative constant D2 > 0")
    p.add_argument("--g", type=number_argument, nargs="+", metavar="V", help="impact speed(s) g > 0")
    p.add_argument("--tol", type=number_argument, default=None,
                   help="relative tolerance in (0, 1) (default 1e-9; with --method and no --tol, that method's own bound)")
    p.add_argument("--method", default=None,
                   help="force one rung of the ladder (it must meet --tol if given), e.g. uniform (the fitted uniform "
                        "approximation; its old name closed-form still works, with a note), master, integrator")
    p.add_argument("--no-build", action="store_true",
                   help="never build the master curve; use only methods that need nothing cached")
    add_end(p)
    p.add_argument("--json", action="store_true", help="machine-readable output")
    return p


def run_eps(args, out) -> None:
    from ..api import epsilon

    physical = (args.D1, args.D2, args.g)
    if args.omega is not None and any(v is not None for v in physical):
        raise ParameterError("omega", args.omega, "give either --omega or all of --D1 --D2 --g, not both")
    if args.omega is None and any(v is None for v in physical):
        missing = next(n for n, v in zip(("--D1", "--D2", "--g"), physical) if v is None)
        raise ParameterError(missing.lstrip("-"), None, "give --omega, or all of --D1 --D2 --g")
    tol = 1e-9 if args.tol is None and args.method is None else args.tol
    kwargs = dict(alpha=args.alpha, gamma=args.gamma, tol=tol, method=args.method,
                  build=False if args.no_build else None, end=args.end)
    if args.omega is not None:
        res = epsilon(omega=args.omega, **kwargs)
    else:
        res = epsilon(g=args.g, D1=args.D1, D2=args.D2, **kwargs)
    eps = [float(e) for e in res.eps.ravel()]
    if args.json:
        extra = {} if res.coefficients is None else {"coefficients": res.coefficients}
        json.dump({"eps": eps, "method": res.method, "error_bound": float(res.error_bound),
                   "methods": res.methods, "parts": [p.as_dict() for p in res.parts], **extra}, out,
                  separators=(", ", ": "))
        out.write("\n")
        return
    # a fitted build's bound is measured on held-out points, not proved: the line says which
    kind = "relative error estimate" if res.method == "uniform" else "relative error bound"
    out.write(f"method {res.method} ({res.setting or 'no setting'}), {kind} "
              f"{res.error_bound:.3g}" + ("" if res.tol is None else f" (tol {res.tol:.3g})") + "\n")
    if len(res.parts) > 1:
        for p in res.parts:
            out.write(f"  {p.method}: {p.count} point(s), Omega {p.omega_min:.6g}..{p.omega_max:.6g}, "
                      f"bound {p.bound:.3g} ({p.setting or 'no setting'})\n")
    out.write(f"{'Omega':>22}  {'eps':>22}\n")
    for w, e in zip(res.omega.ravel(), eps):
        out.write(f"{w:22.15g}  {e:22.15g}\n")


def _omega_from_args(args) -> float:
    physical = [args.D1, args.D2, args.g]
    if args.omega is not None:
        if any(v is not None for v in physical):
            raise UsageError("restitution collide: give either --omega or all of --D1 --D2 --g, not both")
        return args.omega
    if any(v is None for v in physical):
        raise UsageError("restitution collide: give --omega, or all of --D1 --D2 --g")
    from ..core.model import Material
    return Material(args.alpha, args.gamma, args.D1, args.D2).omega(args.g)


def run_series(args, out) -> None:
    from ..core.series import series_for
    ps = series_for((args.alpha, args.gamma), args.omega_order, args.max_power,
                             "inverse" if args.inverse else "forward",
                             # the first k powers cost about k^3.5 (k^2.7 to k^4.2 measured between pairs)
                             progress=Progress("series", "powers of tau", 3.5,
                                                " (an estimate, good to a factor of about two)"))
    data = ps.as_dict()
    if args.json:
        write_json(data, out)
        return
    out.write(f"{data['direction']} collision, alpha = {data['alpha']}, gamma = {data['gamma']}, "
              f"p = {data['p']}: x = sum_n Omega^n x_n(tau)\n")
    out.write(f"{'n':>3}  {'power':>8}  coefficient\n")
    for n, terms in data["orders"].items():
        for power, coeff in terms:
            out.write(f"{n:>3}  {power:>8}  {coeff}\n")


def run_collide(args, out) -> None:
    # an option the chosen method does not read would be dropped without a word
    if args.digits is not None and args.method != "highprec":
        raise UsageError(f"restitution collide: --digits is read by --method highprec only (method here: "
                          f"{args.method}); drop it or add --method highprec")
    if args.rtol is not None and args.method in ("highprec", "closed-form", "exact-family"):
        raise UsageError(f"restitution collide: --rtol is read by --method reference and integrator only; "
                          f"{args.method} sets its own accuracy" + (" (use --digits)" if args.method == "highprec" else ""))
    omega = _omega_from_args(args)
    from ..api import collide
    result = collide(args.alpha, args.gamma, omega, method=args.method,
                     rtol=1e-12 if args.rtol is None else args.rtol,
                     digits=30 if args.digits is None else args.digits, end=args.end).as_dict()
    if args.json:
        write_json(result, out)
        return
    for key, value in result.items():
        shown = f"{value:.12g}" if isinstance(value, float) and math.isfinite(value) else value
        out.write(f"{key:>6}  {shown}\n")


