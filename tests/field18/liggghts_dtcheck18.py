"""Field round 18: the eps LIGGGHTS gives at a deck's own time step over where in a step the contact starts (two
spheres start apart by f g dt, f = 0, 1/N, ...; the spec's lines as round 10's referee builds a LIGGGHTS head-on run),
beside the audit's "eps there A to B" (audit.json eps_at_dt_spread). No import from the project.
usage: python liggghts_dtcheck18.py DECKDIR CHECK_INDEX SPEED_INDEX [N]"""
import json, math, os, subprocess, sys, tempfile


def run(spec, chk, g, dt, gap, nmax):
    r1, m1, r2, m2 = chk["r1"], chk["m1"], chk["r2"], chk["m2"]
    v1, v2 = g * m2 / (m1 + m2), -g * m1 / (m1 + m2)
    L = 50.0 * max(r1, r2)
    lines = [f"units {spec.get('units', 'si')}", "atom_style granular", "atom_modify map array", "boundary f f f", "newton off",
             "communicate single vel yes", f"region box block {-L} {L} {-L} {L} {-L} {L} units box",
             f"create_box {spec.get('ntypes', 2)} box", f"neighbor {0.2 * r1} bin", "neigh_modify delay 0"] + spec["lines"] + [
        f"create_atoms {chk['t1']} single {-r1 - gap / 2} 0 0 units box", f"create_atoms {chk['t2']} single {r2 + gap / 2} 0 0 units box",
        f"set atom 1 diameter {2 * r1} density {m1 / (4 / 3 * math.pi * r1 ** 3)}",
        f"set atom 2 diameter {2 * r2} density {m2 / (4 / 3 * math.pi * r2 ** 3)}",
        "group a1 id 1", "group a2 id 2", f"velocity a1 set {v1} 0 0 units box", f"velocity a2 set {v2} 0 0 units box",
        "variable d equal x[2]-x[1]", "variable vr equal vx[2]-vx[1]", "fix integr all nve/sphere", f"timestep {dt}",
        "thermo_style custom step v_d v_vr", "thermo 1", "thermo_modify format float %.17g norm no", f"run {nmax}"]
    with tempfile.TemporaryDirectory(prefix="field18-ldt.") as tmp:
        open(os.path.join(tmp, "in.r"), "w").write("\n".join(lines) + "\n")
        p = subprocess.run(["liggghts", "-in", "in.r", "-log", "none"], cwd=tmp, capture_output=True, text=True, errors="replace")
    touched = False
    for ln in p.stdout.splitlines():
        f = ln.split()
        if len(f) == 3 and f[0].isdigit():
            d, vr = float(f[1]), float(f[2])
            if d < r1 + r2:
                touched = True
            elif touched:
                return vr / g
    return float("nan")


def main(d, ci, si, n=16):
    spec = json.load(open(os.path.join(d, "spec.json")))
    audit = json.load(open(os.path.join(d, "audit.json")))
    chk = spec["checks"][ci]
    row = [p for p in audit["pairs"] if sorted(p["types"]) == sorted([chk["t1"], chk["t2"]])][chk.get("row", 0)]
    g, dt = row["speeds"][si], row["dt"]
    vals = [run(spec, chk, g, dt, (k / n) * g * dt + 1e-12 * g, 100000) for k in range(n)]
    sp = (row.get("eps_at_dt_spread") or [None] * len(row["speeds"]))[si]
    out = (f"{os.path.basename(d.rstrip('/'))} types {chk['t1']} {chk['t2']} g {g:g} dt {dt:g}: LIGGGHTS over {n} start "
           f"fractions {min(vals):.6f} to {max(vals):.6f}; audit spread {sp}; audit dt->0 {row['eps'][si]:.6f}")
    print(out)
    with open(os.path.join(d, "dtcheck.txt"), "a") as fh:
        fh.write(out + "\n")


if __name__ == "__main__":
    main(sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4]) if len(sys.argv) > 4 else 16)
