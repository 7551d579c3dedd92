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
Then the plans at the report angles (dynamics.plans.plan_sets, built in analyze) and the CPU
time of drawing each plan figure (render/plots_plans.py: build and PNG, as run saves them).
Prints the machine. Target (issue 12): the force analysis adds ≤ 5 ms at 3600 points.
"""
from __future__ import annotations

import argparse
import io
import sys
import time
from dataclasses import replace
from pathlib import Path


ROOT = Path(__file__).resolve().parents[1]
CASE = ROOT / "cases" / "compressor.toml"
TARGET_MS = 5.0

from bench_kinematics import best_ms, machine  # noqa: E402  (the same machine line and timer)


def prepare(points: int):
    """Mechanism, kinematics, ω, ε and loads of the compressor as the run has them (the loads
    built by the pipeline's own force_loads)."""
    from flywheel.cases.run import load_case
    from flywheel.dynamics.grid import standard_positions
    from flywheel.dynamics.pipeline import analyze, force_loads

    case = load_case(CASE)
    res = analyze(case, n_points=points)
    mech = case.mechanism()
    _, dcs = standard_positions(mech)
    loads = force_loads(case, mech, dcs, res.kinematics, res.loads, res.motion.J_I)
    return mech, res.kinematics, res.motion.omega, res.motion.epsilon, loads, \
        res.energy.balancing_moment


def plan_figures_cpu(results, lang: str = "en", repeat: int = 3) -> dict[str, float]:
    """{file name: best CPU seconds} of the plan figures of ``results``: each built and saved
    as `flywheel run` saves it (zlib level 1, no metadata), best of ``repeat`` of
    time.process_time (this process's CPU, so the other load on the machine counts less)."""
    from flywheel.render import plots

    out = {}
    with plots._style():
        plots.figure_omega(results, lang).savefig(io.BytesIO(), format="png")   # warm up
        for name, build in plots.all_figures(results, lang):
            if not name.startswith("plan_"):
                continue
            best = float("inf")
            for _ in range(repeat):
                t = time.process_time()
                fig = build()
                fig.savefig(io.BytesIO(), format="png", dpi=plots.DPI, metadata={"Software": None},
                            pil_kwargs={"compress_level": 1})
                best = min(best, time.process_time() - t)
                fig.clear()
            out[name] = best
    return out


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

    # the plans at the report angles (issue 12 item 6): built in analyze, drawn with the plots
    from flywheel.dynamics import plans

    ld = force_loads(case, mech, dcs, res.kinematics, res.loads, res.motion.J_I)
    plans_ms = best_ms(lambda: plans.plan_sets(mech, res.kinematics, res.forces.analysis, ld,
                                               case.output.at_deg), args.repeat)
    drawn = plan_figures_cpu(res)

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
    print(f"the plans at {len(case.output.at_deg)} report angle(s) (velocity, acceleration, force "
          f"polygons, lever): {plans_ms:.3f} ms")
    print("drawing the plans (build + PNG, CPU of one process, best of 3): "
          + ", ".join(f"{n} {t * 1e3:.0f} ms" for n, t in drawn.items())
          + f"; total {sum(drawn.values()) * 1e3:.0f} ms")
    ok = max(whole, stage_true, stage_steady) <= TARGET_MS
    print("target met" if ok else "TARGET MISSED")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
