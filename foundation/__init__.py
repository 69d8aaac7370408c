"""What every layer shares and no layer owns: the one input-error type (``errors``), file and path
helpers (``io``: atomic writes, output paths, the JSON encoder, folder locks, the one grid parser),
worker processes (``processes``), the packages' lazy re-exports (``lazy``) and an option's help and
default from the library's fields (``fields``)."""
