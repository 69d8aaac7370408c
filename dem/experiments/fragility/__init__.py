"""Fragility: ensembles of perturbed realisations under sine pulses (``run``), the result file
(``file``), the figure (``figure``), the command ``fragility`` and the campaign step ``fragility``."""
