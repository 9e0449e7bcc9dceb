# SPDX-License-Identifier: MIT
"""One argparse parser per tool, its --help taken whole from the tool's docstring.

parser(__doc__, "tools/x.py") gives the docstring's first paragraph as the
description and the rest, unwrapped as written, after the option list; each
option then adds its own help line.
"""
import argparse


def parser(doc, prog):
    head, _, rest = doc.strip().partition("\n\n")
    return argparse.ArgumentParser(prog=prog, description=head, epilog=rest or None,
                                   formatter_class=argparse.RawDescriptionHelpFormatter)


def module_main(doc, prog):
    """A module run as a program: --help describes it, anything else says it has nothing to run."""
    import sys
    parser(doc, prog).parse_args()
    sys.stderr.write("%s: a module the other tools import, nothing to run (--help describes it)\n" % prog)
    sys.exit(2)


if __name__ == "__main__":
    module_main(__doc__, "tools/helptext.py")
