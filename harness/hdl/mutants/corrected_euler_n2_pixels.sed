# SPDX-License-Identifier: MIT OR Apache-2.0
#
# A PLANTED BUG, for harness/hdl/ci.sh, which requires it to FAIL on at least one
# published set: an off-by-one in the pixel count. The counter is loaded
# with n + 1 instead of n, so the unit emits n + 2 pixels instead of n + 1 (one
# step past N_b).
#
# Applied to units/corrected_euler.sv by harness/hdl/ci.sh (sed -f), which checks that it changes
# exactly that one line and that the planted bug FAILS on at least one published set.
80s/left <= in_n;/left <= in_n + 16'd1;  \/\/ PLANTED: one pixel too many/
