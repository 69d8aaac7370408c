"""The tilt test: the run (``run``), its check against limit analysis (``check``), the study case
(``case``), ensembles of imperfect joints (``ensemble``), the result file (``file``), the figure
(``figure``), the commands ``tilt`` and ``calibrate`` and the campaign steps ``tilt``, ``lab`` and ``piers``."""
