"""Builders shared by several test modules (importable as ``helpers``: pytest puts tests/ on
the path)."""
from __future__ import annotations

from functools import lru_cache
from pathlib import Path

import numpy as np

from flywheel.cases.run import load_case, to_mechanism
from flywheel.dynamics import forces as fo
from flywheel.dynamics.pipeline import analyze
from flywheel.linkage import solve
from flywheel.linkage.deadcentres import dead_centres, guide_frame, slider_dyad

CASES = Path(__file__).resolve().parents[1] / "cases"


def case_setup(name: str) -> dict:
    """A bundled case as the force analysis sees it, built here from the case file and the
    pipeline's results: gas forces push each piston away from its cylinder head with the
    magnitude results.cylinders[i].F (reduced moment F·x′·sign(x_far − x_head), loads.py);
    technological forces oppose the slider's velocity (reduced moment −F·|x′|); weights m·g at
    the centroids; J_I = max(J_required, J_first_group) (pipeline.dynamics)."""
    case = load_case(CASES / f"{name}.toml")
    res = analyze(case)
    mech = to_mechanism(case)
    kin = solve(mech, res.phi)
    pf = []
    for cy, cr in zip(case.cylinders, res.cylinders):
        d = slider_dyad(mech, cy.piston)
        u, _ = guide_frame(d)
        dcs = {dc.kind: dc for dc in dead_centres(mech, cy.piston)}
        head, far = dcs[cy.head], dcs["inner" if cy.head == "outer" else "outer"]
        pf.append(fo.PointForce(cy.name, cy.piston, d.joint,
                                (cr.F * np.sign(far.x - head.x))[:, None] * u))
    for f in case.forces:
        d = slider_dyad(mech, f.slider)
        u, _ = guide_frame(d)
        x_dot = kin.points[d.joint].v_q @ u
        F = res.columns[f"F_{f.name}"].values
        pf.append(fo.PointForce(f.name, f.slider, d.joint, (-F * np.sign(x_dot))[:, None] * u))
    s = res.scalars
    J_I = max(s.J_required, s.J_first_group)
    loads = fo.Loads(case.links, tuple(pf),
                     tuple(fo.Couple(c.name, c.link, c.moment) for c in case.couples),
                     tuple(case.machine.gravity), J_I)
    return {"case": case, "res": res, "mech": mech, "kin": kin, "loads": loads,
            "omega": res.columns["omega"].values, "eps": res.columns["epsilon"].values,
            "M_D": s.balancing_moment, "J_I": J_I}


# numerical derivatives: 8th-order central differences (as tests/linkage/test_kinematics.py)
_D1 = np.array([1 / 280, -4 / 105, 1 / 5, -4 / 5, 0.0, 4 / 5, -1 / 5, 4 / 105, -1 / 280])
_D2 = np.array([-1 / 560, 8 / 315, -1 / 5, 8 / 5, -205 / 72, 8 / 5, -1 / 5, 8 / 315, -1 / 560])


def check_numerical(mech, phi0, scale) -> int:
    """Every point's and link's velocity and acceleration analogue of ``mech`` at the angles
    ``phi0`` [rad] against 8th-order central differences of the positions (points to
    1e-8·``scale`` [m]); returns how many analogues were checked."""
    k = solve(mech, phi0)
    offs = np.arange(-4, 5)
    checked = 0
    for h, w, order in ((1e-3, _D1, 1), (4e-3, _D2, 2)):
        kk = solve(mech, (phi0[:, None] + h * offs[None, :]).ravel())
        for name, pm in kk.points.items():
            num = np.einsum("k,nkj->nj", w, pm.r.reshape(phi0.size, 9, 2)) / h ** order
            exact = k.points[name].v_q if order == 1 else k.points[name].a_q
            np.testing.assert_allclose(exact, num, rtol=1e-8, atol=1e-8 * scale, err_msg=name)
            checked += 1
        for name, lm in kk.links.items():
            th = lm.theta.reshape(phi0.size, 9)
            th = th[:, 4:5] + np.angle(np.exp(1j * (th - th[:, 4:5])))
            exact = k.links[name].omega_q if order == 1 else k.links[name].eps_q
            np.testing.assert_allclose(exact, (th @ w) / h ** order, rtol=1e-8, atol=1e-8,
                                       err_msg=name)
            checked += 1
    return checked


def err_text(res) -> str:
    """The stderr of a typer CliRunner result (older click mixes the streams: its output)."""
    try:
        return res.stderr
    except (ValueError, AttributeError):
        return res.output


#: a number as the Russian policy writes it (render/numbers.py): true minus, narrow spaces
#: between thousands, decimal comma; and as English writes it
NUMBER_RU = r"(?<![\w,])[\u2212-]?\d+(?:\u202f\d{3})*(?:,\d+)?"
NUMBER_EN = r"(?<!\w)-?\d+(?:\.\d+)?(?:e[+-]?\d+)?"


def ru_numbers(text: str) -> list[float]:
    """The numbers of a Russian text, as floats."""
    import re

    return [float(x.replace("\u2212", "-").replace("\u202f", "").replace(",", "."))
            for x in re.findall(NUMBER_RU, text)]


def en_numbers(text: str) -> list[float]:
    """The numbers of an English text, as floats."""
    import re

    return [float(x) for x in re.findall(NUMBER_EN, text)]


def same_numbers(ru: list[float], en: list[float], rel: float = 5e-4,
                 noise: float = 1e-9) -> bool:
    """The Russian numbers are the English ones to the Russian policy's four significant
    digits (or its round-off to 0 below the noise)."""
    return len(ru) == len(en) and all(abs(r - e) <= rel * abs(e) + noise for r, e in zip(ru, en))


def flywheel_in_process(*args, cwd, columns: int = 100):
    """``python -m flywheel ARGS`` run in ``cwd``, in this process (typer's CliRunner: the
    same command line, without an interpreter started per call): an object with ``returncode``,
    ``stdout`` and ``stderr`` like subprocess.run's. For tests whose point is the command, not
    the process (those that start one are marked slow, tests/conftest.py)."""
    import os
    from types import SimpleNamespace

    from typer.testing import CliRunner

    from flywheel.cli import app

    here = os.getcwd()
    os.chdir(cwd)
    try:
        res = CliRunner().invoke(app, [str(a) for a in args], env={"COLUMNS": str(columns)})
    finally:
        os.chdir(here)
    if res.exception is not None and not isinstance(res.exception, SystemExit):
        raise res.exception
    return SimpleNamespace(returncode=res.exit_code, stdout=res.stdout, stderr=err_text(res))


def source_nodes(path) -> tuple:
    """Every node of a Python file's syntax tree, in ast.walk's order, parsed once per session
    (the tests that read the package's source share it): read-only."""
    return _source_nodes(Path(path).resolve())


@lru_cache(maxsize=None)
def _source_nodes(path: Path) -> tuple:
    import ast

    return tuple(ast.walk(ast.parse(path.read_text(encoding="utf-8"))))
