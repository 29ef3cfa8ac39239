import sys

from xodrcheck.cli import main

sys.exit(main())
