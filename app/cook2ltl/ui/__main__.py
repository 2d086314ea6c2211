"""`python -m cook2ltl.ui [RECIPE]`: the app without the CLI around it."""

import sys

from cook2ltl.errors import UserError
from cook2ltl.ui.app import run_app

try:
    run_app(sys.argv[1] if len(sys.argv) > 1 else None)
except UserError as error:
    sys.exit(str(error))
