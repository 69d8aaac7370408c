"""Ground motions and spectra: pulses and sines (``inputs``), recorded accelerograms (``records``),
the codes' elastic spectra (``spectra``) and records matched to a site (``matching``)."""
