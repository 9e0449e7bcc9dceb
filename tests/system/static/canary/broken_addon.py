# SPDX-License-Identifier: MIT
"""An addon that fails the way the MISRA addon can (an exception while it
reads a dump): the negative control tests/system/static/test-cppcheck-misra-control.sh
needs cppcheck-misra.sh to report it as a failure, never as 0 findings."""
raise RuntimeError("canary addon: internal error on purpose")
