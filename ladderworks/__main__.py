"""`python -m ladderworks` starts the IDE."""

import sys

from ladderworks.gui.app import main

sys.exit(main())
