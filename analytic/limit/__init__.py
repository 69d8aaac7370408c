"""Limit analysis: the continuous ring (``limit_continuous``), the discrete enumeration and the
static LP with friction (``limit_discrete``), arches on piers (``limit_piers``), hinge layouts
(``layout``), the two-bar sliding model (``two_bar``), all of them at once (``summary``), the
imperfect fit calibrated on laboratory tilts (``calibration``) and their figures (``figures``)."""
