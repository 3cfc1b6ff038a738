# SPDX-License-Identifier: MIT OR Apache-2.0
#
# A PLANTED BUG, for harness/hdl/ci.sh, which requires it to FAIL on at least one
# published set: an off-by-one in the pixel count. The counter is loaded
# with n - 1 instead of n, so the unit emits n pixels instead of n + 1 (pixel n,
# at N_b, is missing).
#
# Applied to units/gouraud.sv by harness/hdl/ci.sh (sed -f), which checks that it changes
# exactly that one line and that the planted bug FAILS on at least one published set.
70s/left <= in_n;/left <= in_n - 16'd1;  \/\/ PLANTED: n counted as the pixels, not the steps/
