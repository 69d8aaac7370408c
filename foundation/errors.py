"""The one exception type for bad user input, shared by every package.

The CLI turns it into a one-line message on stderr and exit code 2.
"""


class ArchdemInputError(ValueError):
    """Bad input from the user (geometry, parameters, files, units)."""
