"""``python -m mechverify.cli``."""

import sys

from mechverify.cli import main

sys.exit(main())
