// SPDX-License-Identifier: MIT OR Apache-2.0
//
// Adaptive span unit (eq. 24, K_d = 1): decides per span between Gouraud and
// corrected Euler from the rounded set-up, in exact integers, then runs the pick.
//
//   k = ceil(n/2) = (n + 1) >> 1,  T = k(k - 1)/2,
//   delta = k*dp - k*t0 - T*ds     (raw, exact: no rounding anywhere)
//   Gouraud iff 255*|delta| < 2^F, else corrected Euler;
//   Gouraud:         p_0 = p0; p_{i+1} = p_i + dp
//   corrected Euler: p_0 = p0, t_0 = t0; p_{i+1} = p_i + t_i, t_{i+1} = t_i + ds
//   out_value = p_i for i = 0..n.
//
// delta is computed without a multiplier, as 2*delta = k*(2(dp - t0) - (k - 1)*ds)
// (k(k - 1) is even, so the halving is exact): two shift-and-add products, one bit of
// the multiplier (k - 1, then k) per clock, in an accumulator of W + 32 bits
// (|2*delta| < 2^(W+31) for n < 2^16). The comparison is exact: 255*|delta| in
// W + 40 bits against 2^F.
// The loop is the corrected-Euler loop (two W-bit adders); Gouraud runs on it with
// t = dp, ds = 0, which is g_{i+1} = g_i + dp exactly. Additions are exact unless a
// register overflows (wraps).
// Set-up: p0 = p_a, dp = (p_b - p_a)/n, t0 (eq. 17) and ds are computed on the host,
// exactly, and rounded once to nearest (`phong-approx setup --method adaptive`): each
// is off by at most h = 2^-(F+1), the assumption of proofs/Fixed.v.
// Bound: delta is within e = h(2k + T) of the exact delta
// (fixed_point_adaptive_delta_error), so the pick is the exact test's wherever
// |255*|delta_exact| - 1| > 255*e (fixed_point_adaptive_decision); the picked loop is then within its own bound of the
// exact run of the picked method: h(1 + n) for Gouraud (fixed_point_gouraud_error),
// h(1 + n + n(n-1)/2) for corrected Euler (fixed_point_corrected_euler_error).
// Latency: pixel 0 is valid b(k - 1) + b(k) + 4 cycles after the set-up is taken,
// b(x) the bit length of x (5 cycles at n = 1 or 2, at most 35 at n = 65535).
// Throughput: then one pixel per clock while out_ready is high. in_ready is low from
// the set-up until pixel n leaves.
//
// Ports (every unit of harness/hdl has these; docs/conformance.md, "Hardware span
// units"):
//   clk, rst         clock; synchronous reset, active high
//   in_valid/ready   one span's set-up is taken on a cycle with both high
//   in_n             steps n >= 1: the unit emits n + 1 pixels
//   in_p0, in_dp, in_t0, in_ds   the set-up this unit uses (raw, W bits)
//   in_q0, in_dq0, in_d2q        unused here
//   out_valid/ready  one pixel leaves on a cycle with both high; out_ready may stay
//                    low for any number of cycles (the pixel is held)
//   out_value        the pixel (raw, W bits)
//   out_last         high with pixel n
module adaptive #(
    parameter int M = 8,
    parameter int F = 40
) (
    input  logic                  clk,
    input  logic                  rst,
    input  logic                  in_valid,
    output logic                  in_ready,
    input  logic [15:0]           in_n,
    input  logic signed [M+F-1:0] in_p0,
    input  logic signed [M+F-1:0] in_dp,
    input  logic signed [M+F-1:0] in_t0,
    input  logic signed [M+F-1:0] in_ds,
    // The common ports this method does not use.
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
  localparam int AW = W + 32;  // the accumulator of 2*delta
  localparam int CW = AW + 8;  // 255*|delta|

  typedef enum logic [2:0] {
    IDLE,    // waiting for a set-up
    MUL1,    // acc = (k - 1)*ds
    MUL2,    // acc = k*(2(dp - t0) - (k - 1)*ds) = 2*delta
    DECIDE,  // the exact test, and the loop's start
    RUN      // the pixels
  } state_t;
  state_t state;

  logic [15:0]          n;      // steps
  logic [15:0]          k;      // ceil(n/2)
  logic signed [W-1:0]  p0, dp, t0, ds;
  logic [15:0]          mbits;  // the multiplier's bits not yet used
  logic signed [AW-1:0] mcand;  // the multiplicand, shifted left one bit per clock
  logic signed [AW-1:0] acc;

  logic signed [W-1:0]  p;      // the pixel on out_value
  logic signed [W-1:0]  t;      // its slope (dp under Gouraud)
  logic signed [W-1:0]  dt;     // the slope's step (0 under Gouraud)
  logic [15:0]          left;   // pixels after the one on out_value

  // k = (n + 1) >> 1 = (n >> 1) + (n & 1), at most 32768.
  logic [15:0] in_k;
  assign in_k = {1'b0, in_n[15:1]} + {15'd0, in_n[0]};

  // The test, on the finished accumulator: delta = acc / 2 (exact).
  logic signed [AW-1:0] delta, mag;
  logic [CW-1:0]        mag255;
  logic                 gouraud;
  assign delta   = acc >>> 1;
  assign mag     = (delta < 0) ? -delta : delta;
  assign mag255  = (CW'(mag) << 8) - CW'(mag);
  assign gouraud = mag255 < (CW'(1) << F);

  assign in_ready  = (state == IDLE);
  assign out_valid = (state == RUN);
  assign out_value = p;
  assign out_last  = (left == 16'd0);

  always_ff @(posedge clk) begin
    if (rst) begin
      state <= IDLE;
    end else begin
      unique case (state)
        IDLE:
          if (in_valid) begin
            n     <= in_n;
            k     <= in_k;
            p0    <= in_p0;
            dp    <= in_dp;
            t0    <= in_t0;
            ds    <= in_ds;
            mbits <= in_k - 16'd1;
            mcand <= AW'(in_ds);
            acc   <= '0;
            state <= MUL1;
          end
        MUL1, MUL2:
          if (mbits == 16'd0) begin
            if (state == MUL1) begin
              mbits <= k;
              mcand <= ((AW'(dp) - AW'(t0)) <<< 1) - acc;
              acc   <= '0;
              state <= MUL2;
            end else begin
              state <= DECIDE;
            end
          end else begin
            if (mbits[0]) acc <= acc + mcand;
            mcand <= mcand <<< 1;
            mbits <= mbits >> 1;
          end
        DECIDE: begin
          p     <= p0;
          t     <= gouraud ? dp : t0;
          dt    <= gouraud ? '0 : ds;
          left  <= n;
          state <= RUN;
        end
        RUN:
          if (out_ready) begin
            if (out_last) state <= IDLE;
            p    <= p + t;
            t    <= t + dt;
            left <= left - 16'd1;
          end
        default: state <= IDLE;
      endcase
    end
  end
endmodule
