"""The virtual experiments, one package each: everything one experiment is (its run, result type,
study case, file, figure, commands and campaign steps) in one folder (docs/architecture.md)."""
