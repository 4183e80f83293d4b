"""`python -m ladderworks.cli` runs the command line."""

from ladderworks.cli import run

run()
