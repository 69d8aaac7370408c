"""The shake table: one run (``run``), thresholds (``thresholds``), DEM failure domains (``domain``),
the result file (``file``), figures and animations (``figure``, ``animation``), the commands ``shake``,
``threshold``, ``animate``, ``domain`` and ``rock`` and the campaign step ``shake``."""
