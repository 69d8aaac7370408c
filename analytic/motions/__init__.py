"""Ground motions and spectra: pulses and sines (``inputs``), recorded accelerograms (``records``),
the codes' elastic spectra (``spectra``), records matched to a site (``matching``) and a shake table whose
servo cannot exceed a speed (``table``)."""
