"""Limit analysis: the continuous ring (``limit_continuous``), the discrete enumeration and the
static LP with friction (``limit_discrete``), the least collapse with friction
without dilatancy (``non_associative``), arches on piers (``limit_piers``), hinge layouts
(``layout``), the two-bar sliding model (``two_bar``), all of them at once (``summary``), the
imperfect fit calibrated on laboratory tilts (``calibration``), tie-rods as tension members of the LP
and their work in a mechanism (``ties``) and their figures (``figures``)."""
