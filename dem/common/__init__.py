"""What the experiments share: the groups of the result files (``hdf5``), what a campaign step gets
(``campaign``) and the command line's shared options (``options``)."""
