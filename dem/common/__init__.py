"""What the experiments share: the groups of the result files (``hdf5``), what a campaign step gets
(``campaign``), the figure writer (``figures``), an arch's stored parameters (``arch``), the bounds of a
sine pulse on the command line (``limits``) and the command line's shared options (``options``)."""
