"""The fixed margins of the scenes whose figures skip ``tight_layout`` at their registered settings
(``scenes.common.layout``): they must be the margins ``tight_layout`` gives those figures, or texts would be cut
or the figure would change; at other settings the scenes fall back to ``tight_layout``."""
from __future__ import annotations

import dataclasses

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import pytest  # noqa: E402

from knifeedge.scenes import SCENE_NAMES, get_scene  # noqa: E402
from knifeedge.scenes.common import layout  # noqa: E402

#: the scenes that lay out their figure with fixed margins (all: a tight layout costs 0.05-0.5 s a figure)
FIXED = SCENE_NAMES
KEYS = ("left", "right", "bottom", "top", "wspace", "hspace")


def _margins(fig) -> dict:
    return {k: getattr(fig.subplotpars, k) for k in KEYS}


#: margins no tight layout gives the small figure of :func:`_laid_out`
MARGINS = dict(left=0.3, right=0.9, bottom=0.2, top=0.8, wspace=0.5)


def _laid_out(registered: bool) -> dict:
    """The margins :func:`layout` gives a small two-axes figure with a label, asked for :data:`MARGINS`."""
    fig = plt.figure(figsize=(4, 3))
    ax1, ax2 = fig.subplots(1, 2)
    ax1.set_ylabel("a label")
    layout(fig, registered, MARGINS)
    got = _margins(fig)
    plt.close(fig)
    return got


def test_layout_uses_the_margins_at_the_registered_settings_and_tight_layout_elsewhere():
    for registered in (True, False):
        got = _laid_out(registered)
        same = all(got[k] == pytest.approx(v) for k, v in MARGINS.items())
        assert same == registered, got


def test_a_users_style_gets_the_tight_layout_not_the_fixed_margins():
    """A matplotlibrc or style with other font sizes moves the texts: the fixed margins would cut them."""
    with matplotlib.rc_context({"font.size": 16}):
        got = _laid_out(True)
    assert got["left"] != pytest.approx(MARGINS["left"]), got


@pytest.mark.slow
@pytest.mark.parametrize("name", FIXED)
def test_fixed_margins_are_what_tight_layout_gives_the_registered_figure(name):
    result = get_scene(name)()
    fixed = result.figure(110)
    other = dataclasses.replace(result, scene=dataclasses.replace(result.scene))  # not the registered object
    tight = other.figure(110)
    try:
        a, b = _margins(fixed), _margins(tight)
        assert a != _margins(plt.figure())  # the fixed margins were set (not matplotlib's defaults)
        for k in KEYS:  # 1e-4 of the figure: under 0.1 pixel at 110 dpi
            assert a[k] == pytest.approx(b[k], abs=1e-4), (k, a, b)
    finally:
        plt.close("all")
