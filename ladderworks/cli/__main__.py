"""`python -m ladderworks.cli` runs the command line."""

import sys

from ladderworks.cli import main

sys.exit(main())
