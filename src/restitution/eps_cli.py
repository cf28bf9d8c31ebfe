"""`restitution eps`: eps to a tolerance by the cheapest adequate method (wired into cli.py by the lead).

    restitution eps --alpha 3/2 --gamma 1 (--omega W [W ...] | --D1 a --D2 b --g v [v ...])
                    [--tol t] [--method NAME] [--no-build] [--json]

--json prints {"eps": [...], "method": "...", "error_bound": ...}. Bad input raises ParameterError
(the CLI prints one line and exits 2); progress of a first-time master-curve build goes to stderr.
"""

from __future__ import annotations

import argparse
import json

from .errors import ParameterError
from .exponents import number_argument

__all__ = ["add_eps_subcommand", "run_eps"]


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
    p.add_argument("--tol", type=number_argument, default=1e-9, help="relative tolerance in (0, 1) (default 1e-9)")
    p.add_argument("--method", default=None,
                   help="force one rung of the ladder (it must still meet --tol), e.g. master, integrator")
    p.add_argument("--no-build", action="store_true",
                   help="never build the master curve; use only methods that need nothing cached")
    p.add_argument("--json", action="store_true", help="machine-readable output")
    return p


def run_eps(args, out) -> None:
    from .ladder import epsilon

    physical = (args.D1, args.D2, args.g)
    if args.omega is not None and any(v is not None for v in physical):
        raise ParameterError("omega", args.omega, "give either --omega or all of --D1 --D2 --g, not both")
    if args.omega is None and any(v is None for v in physical):
        missing = next(n for n, v in zip(("--D1", "--D2", "--g"), physical) if v is None)
        raise ParameterError(missing.lstrip("-"), None, "give --omega, or all of --D1 --D2 --g")
    kwargs = dict(alpha=args.alpha, gamma=args.gamma, tol=args.tol, method=args.method,
                  build=False if args.no_build else None)
    if args.omega is not None:
        res = epsilon(omega=args.omega, **kwargs)
    else:
        res = epsilon(g=args.g, D1=args.D1, D2=args.D2, **kwargs)
    eps = [float(e) for e in res.eps.ravel()]
    if args.json:
        json.dump({"eps": eps, "method": res.method, "error_bound": float(res.error_bound)}, out,
                  separators=(", ", ": "))
        out.write("\n")
        return
    out.write(f"method {res.method} ({res.setting or 'no setting'}), relative error bound "
              f"{res.error_bound:.3g} (tol {res.tol:.3g})\n")
    out.write(f"{'Omega':>22}  {'eps':>22}\n")
    for w, e in zip(res.omega.ravel(), eps):
        out.write(f"{w:22.15g}  {e:22.15g}\n")
