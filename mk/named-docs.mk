# SPDX-License-Identifier: MIT
# The manual works as written and every program explains itself:
#   tests/tools/test_doc_commands.py      every shell block of README.md and docs/*.md runs
#   tests/tools/test_tools_help.py        every tool's --help: complete, no side effects
#   tests/host-sim/test_squeal_sim_help.py  every squeal-sim command's description is a whole sentence
#   tests/tools/test_deps.py              tools/deps.py: a missing module names its Debian package
#   tests/tools/test_helptext.py          tools/helptext.py: --help from the docstring
#   tests/tools/test_flash.py             tools/flash.sh without hardware (OpenOCD stubbed)
DOC_SIMS := build/host/squeal-sim build/host/squeal-replay build/host-fixed/squeal-sim build/host-fixed/squeal-replay
tests/tools/test_doc_commands.py: $(DOC_SIMS)
tests/host-sim/test_squeal_sim_help.py: $(DOC_SIMS)
TEST_PROGS += tests/tools/test_doc_commands.py tests/tools/test_tools_help.py \
	tests/host-sim/test_squeal_sim_help.py tests/tools/test_deps.py tests/tools/test_helptext.py \
	tests/tools/test_flash.py
