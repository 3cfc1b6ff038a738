# SPDX-License-Identifier: MIT OR Apache-2.0
#
# A PLANTED BUG, for harness/hdl/ci.sh, which requires it to FAIL on at least one
# published set: the divider drops a bit. Its loop runs W - 2 iterations
# instead of W - 1, so the quotient lacks its last bit: (p * 2^F / s) / 2, about
# half the value.
#
# Applied to units/duff.sv by harness/hdl/ci.sh (sed -f), which checks that it changes
# exactly that one line and that the planted bug FAILS on at least one published set.
196s/d_cnt  <= 8'(QB);/d_cnt  <= 8'(QB - 1);  \/\/ PLANTED: one iteration short/
