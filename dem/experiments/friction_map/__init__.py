"""The friction map: the rocking/sliding threshold friction mu* (``run``), the figure (``figure``),
the command ``map`` and the campaign step ``map``."""
