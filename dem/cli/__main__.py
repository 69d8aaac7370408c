import sys

from dem.cli import main

sys.exit(main())
