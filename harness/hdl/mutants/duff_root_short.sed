# SPDX-License-Identifier: MIT OR Apache-2.0
#
# A PLANTED BUG, for harness/hdl/ci.sh, which requires it to FAIL on at least one
# published set: the square root drops a bit. Its digit recurrence runs
# K - 1 iterations instead of K, so the root lacks its last bit: about
# sqrt(q * 2^F) / 2, and the pixel about twice its value.
#
# Applied to units/duff.sv by harness/hdl/ci.sh (sed -f), which checks that it changes
# exactly that one line and that the planted bug FAILS on at least one published set.
175s/s_cnt  <= 8'(K);/s_cnt  <= 8'(K - 1);  \/\/ PLANTED: one iteration short/
