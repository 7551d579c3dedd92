"""flywheel: dynamic analysis of machines and flywheel sizing (the TMM course pipeline).

Library use::

    from flywheel import load_case, analyze
    results = analyze(load_case("cases/compressor.toml"))

Heavy modules (numpy, scipy, pydantic) load only when first needed.
"""

__version__ = "0.1.0"


def load_case(path):
    """Read and validate a case file (TOML) into a :class:`flywheel.cases.run.Case`."""
    from flywheel.cases.run import load_case as _load

    return _load(path)


def analyze(case, **kwargs):
    """Run the whole pipeline on a validated case; returns :class:`flywheel.dynamics.results.Results`."""
    from flywheel.dynamics.pipeline import analyze as _analyze

    return _analyze(case, **kwargs)
