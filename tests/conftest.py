"""Shared test fixtures."""
import sys

import pytest


@pytest.fixture(autouse=True)
def _close_pyplot_figures():
    """Tests draw figures; pyplot keeps the ones it made and past 20 open it warns (an error
    here, RuntimeWarnings being errors): close them after every test, whatever its order."""
    yield
    plt = sys.modules.get("matplotlib.pyplot")
    if plt is not None:
        plt.close("all")
