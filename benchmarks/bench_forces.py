"""Speed of the force analysis on the compressor (issue 12; run by hand, never a timed test):

    python benchmarks/bench_forces.py [--points N] [--repeat R]

Prepares once what the pipeline would hand over — the kinematics on a grid of N points, the
true ω(φ), ε(φ) (here the pipeline's own, on its grid of N intervals), the gas forces as
vectors, the links' masses, gravity and J_I — and then times in-process (timeit, best of many
repeats) the force analysis itself, ``forces.kinetostatics`` (every reaction, M_y, the
slider-crank quantities, the shaking force and moment), the two other balancing moments
(Zhukovsky's lever, the power balance) and all three together; then the stage as `flywheel
run` calls it, ``stages.force_analysis`` (the three, the crank-pin load, the closure; with
``steady`` the true motion's kinetostatics a second time for the closure) with the loads built
from the case (``pipeline.force_loads``), and summary.json's document with and without it.
Prints the machine. Target (issue 12): the force analysis adds ≤ 5 ms at 3600 points.
"""
from __future__ import annotations

import argparse
import os
import platform
import sys
import timeit
from dataclasses import replace
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
CASE = ROOT / "cases" / "compressor.toml"
TARGET_MS = 5.0


def cpu_model() -> str:
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "?"


def machine() -> str:
    try:
        nproc = len(os.sched_getaffinity(0))
    except AttributeError:  # not on Linux
        nproc = os.cpu_count()
    return (f"{platform.platform()} ({platform.machine()}), {cpu_model()}; "
            f"nproc {nproc}; Python {platform.python_version()}; numpy {np.__version__}")


def best_ms(stmt, repeat: int) -> float:
    """Best time of one call [ms]: timeit picks a loop count for ~0.2 s, best of ``repeat``."""
    timer = timeit.Timer(stmt)
    number, _ = timer.autorange()
    return min(timer.repeat(repeat=repeat, number=number)) / number * 1e3


def prepare(points: int):
    """Mechanism, kinematics, ω, ε and loads of the compressor as the pipeline has them."""
    from flywheel.cases.run import load_case, to_mechanism
    from flywheel.dynamics import forces as fo
    from flywheel.dynamics.pipeline import analyze
    from flywheel.linkage import solve
    from flywheel.linkage.deadcentres import dead_centres, guide_frame, slider_dyad

    case = load_case(CASE)
    res = analyze(case, n_points=points)
    mech = to_mechanism(case)
    kin = solve(mech, res.phi)
    pf = []
    for cy, cr in zip(case.cylinders, res.cylinders):     # gas pushes away from the head
        d = slider_dyad(mech, cy.piston)
        u, _ = guide_frame(d)
        dcs = {dc.kind: dc for dc in dead_centres(mech, cy.piston)}
        head, far = dcs[cy.head], dcs["inner" if cy.head == "outer" else "outer"]
        pf.append(fo.PointForce(cy.name, cy.piston, d.joint,
                                (cr.F * np.sign(far.x - head.x))[:, None] * u))
    s = res.scalars
    loads = fo.Loads(case.links, tuple(pf), (), tuple(case.machine.gravity),
                     max(s["J_required"], s["J_first_group"]))
    return mech, kin, res.columns["omega"].values, res.columns["epsilon"].values, loads, \
        s["balancing_moment"]


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--points", type=int, default=3600, help="φ grid intervals (default 3600)")
    ap.add_argument("--repeat", type=int, default=15, help="timeit repeats (default 15)")
    args = ap.parse_args()

    from flywheel.dynamics import forces as fo

    mech, kin, w, e, loads, M_D = prepare(args.points)
    a = (mech, kin, w, e, loads)

    kineto = best_ms(lambda: fo.kinetostatics(*a), args.repeat)
    zhuk = best_ms(lambda: fo.zhukovsky_moment(*a), args.repeat)
    power = best_ms(lambda: fo.power_balance_moment(*a), args.repeat)
    whole = best_ms(lambda: (fo.kinetostatics(*a), fo.zhukovsky_moment(*a),
                             fo.power_balance_moment(*a)), args.repeat)

    from flywheel.cases.run import load_case
    from flywheel.dynamics import stages
    from flywheel.dynamics.grid import standard_positions
    from flywheel.dynamics.pipeline import analyze, force_loads

    case = load_case(CASE)
    res = analyze(case, n_points=args.points)
    _, dcs = standard_positions(mech)

    def stage(motion):
        ld = force_loads(case, mech, dcs, res.kinematics, res.loads, res.motion.J_I)
        return stages.force_analysis(res.phi, res.reduction, res.energy, res.motion,
                                     case.machine.omega_mean, motion, mech, res.kinematics, ld)

    stage_true = best_ms(lambda: stage("true"), args.repeat)
    stage_steady = best_ms(lambda: stage("steady"), args.repeat)
    bare = replace(res, forces=None)
    doc_with = best_ms(lambda: res.to_document(), args.repeat)
    doc_without = best_ms(lambda: bare.to_document(), args.repeat)

    fa = fo.kinetostatics(*a)
    print(f"machine: {machine()}")
    print(f"case: {CASE.relative_to(ROOT)}; grid: {kin.phi.size} nodes; "
          f"{len(fa.joints)} reactions, {len(fa.slider_crank)} slider-crank groups")
    print(f"kinetostatics (reactions, M_y, slider-crank, frame): {kineto:7.3f} ms  "
          f"({kineto / kin.phi.size * 1e6:.0f} ns per node; target ≤ {TARGET_MS:g} ms)")
    print(f"  Zhukovsky's lever alone:                          {zhuk:7.3f} ms")
    print(f"  power balance alone:                              {power:7.3f} ms")
    print(f"all three balancing moments:                        {whole:7.3f} ms")
    print(f"the run's stage, motion true (loads from the case + all of it): {stage_true:7.3f} ms")
    print(f"the run's stage, motion steady (+ the true kinetostatics):    {stage_steady:7.3f} ms")
    print(f"summary.json document: {doc_with:.3f} ms with the force analysis, "
          f"{doc_without:.3f} ms without")
    print(f"closure max|M_y − M_D|/|M_D| = {fo.closure(fa, M_D):.2e} (M_D = {M_D:.6g} N·m)")
    ok = max(whole, stage_true, stage_steady) <= TARGET_MS
    print("target met" if ok else "TARGET MISSED")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
