// SPDX-License-Identifier: MIT OR Apache-2.0
//
// Corrected Euler span unit (eqs. 15-17), and plain Euler (eqs. 12-14) with the
// same file: p_0 = p0, t_0 = t0; p_{i+1} = p_i + t_i, t_{i+1} = t_i + ds;
// out_value = p_i for i = 0..n. The two methods differ only in the host's set-up
// (t0 = t_0 of eq. 17 for corrected Euler, t0 = di_a for plain Euler; ds the same),
// so harness/hdl/run.sh takes this file for both: --method corrected-euler or
// --method euler.
//
// Arithmetic: signed fixed point M.F in W = M + F bits (value = raw * 2^-F), two
// W-bit adders working in the same cycle. The additions are exact unless a register
// overflows (wraps).
// Set-up: p0 = p_a, t0 and ds are computed on the host, exactly, and rounded once to
// nearest (`phong-approx setup --method corrected-euler` or `--method euler`): each is
// off by at most h = 2^-(F+1), the assumption of proofs/Fixed.v. The unit only adds.
// Bound: pixel i is within h(1 + i + i(i-1)/2) of the exact run of the method, so
// every pixel within h(1 + n + n(n-1)/2) (fixed_point_corrected_euler_error and, for
// the plain-Euler set-up, fixed_point_euler_error; proofs/Fixed.v).
// Latency: pixel 0 is valid the cycle after the set-up is taken. Throughput: one
// pixel per clock while out_ready is high; a span of n + 1 pixels occupies the unit
// n + 2 cycles (in_ready is low from the set-up until pixel n leaves).
//
// Ports (every unit of harness/hdl has these; docs/conformance.md, "Hardware span
// units"):
//   clk, rst         clock; synchronous reset, active high
//   in_valid/ready   one span's set-up is taken on a cycle with both high
//   in_n             steps n >= 1: the unit emits n + 1 pixels
//   in_p0, in_t0, in_ds   the set-up this unit uses (raw, W bits)
//   in_dp, in_q0, in_dq0, in_d2q   unused here
//   out_valid/ready  one pixel leaves on a cycle with both high; out_ready may stay
//                    low for any number of cycles (the pixel is held)
//   out_value        the pixel (raw, W bits)
//   out_last         high with pixel n
module corrected_euler #(
    parameter int M = 8,
    parameter int F = 40
) (
    input  logic                  clk,
    input  logic                  rst,
    input  logic                  in_valid,
    output logic                  in_ready,
    input  logic [15:0]           in_n,
    input  logic signed [M+F-1:0] in_p0,
    // The common ports this method does not use.
    /* verilator lint_off UNUSEDSIGNAL */
    input  logic signed [M+F-1:0] in_dp,
    /* verilator lint_on UNUSEDSIGNAL */
    input  logic signed [M+F-1:0] in_t0,
    input  logic signed [M+F-1:0] in_ds,
    /* verilator lint_off UNUSEDSIGNAL */
    input  logic signed [M+F-1:0] in_q0,
    input  logic signed [M+F-1:0] in_dq0,
    input  logic signed [M+F-1:0] in_d2q,
    /* verilator lint_on UNUSEDSIGNAL */
    output logic                  out_valid,
    input  logic                  out_ready,
    output logic signed [M+F-1:0] out_value,
    output logic                  out_last
);
  localparam int W = M + F;

  logic                busy;  // a span is in the unit
  logic [15:0]         left;  // pixels after the one on out_value
  logic signed [W-1:0] p;     // the pixel on out_value
  logic signed [W-1:0] t;     // its slope
  logic signed [W-1:0] ds;

  assign in_ready  = !busy;
  assign out_valid = busy;
  assign out_value = p;
  assign out_last  = (left == 16'd0);

  // Only the control is reset; p, t and ds are loaded with every set-up.
  always_ff @(posedge clk) begin
    if (rst) begin
      busy <= 1'b0;
      left <= 16'd0;
    end else if (in_valid && in_ready) begin
      busy <= 1'b1;
      left <= in_n;
    end else if (out_valid && out_ready) begin
      if (out_last) busy <= 1'b0;
      left <= left - 16'd1;
    end
  end

  always_ff @(posedge clk) begin
    if (in_valid && in_ready) begin
      p  <= in_p0;
      t  <= in_t0;
      ds <= in_ds;
    end else if (out_valid && out_ready) begin
      p <= p + t;
      t <= t + ds;
    end
  end
endmodule
