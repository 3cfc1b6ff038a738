// SPDX-License-Identifier: MIT OR Apache-2.0
//
// Duff span unit (eqs. 5-7): p/sqrt(q) by forward differences, with an integer
// square root and a divider that each produce one bit per clock.
//
//   p_0 = p0, q_0 = q0, dq_0 = dq0;
//   p_{i+1} = p_i + dp;  q_{i+1} = q_i + dq_i;  dq_{i+1} = dq_i + d2q
//   s_i = floor(sqrt(q_i * 2^F))            (raw of a value in (sqrt(q) - 2^-F, sqrt(q)])
//   out_value = (p_i * 2^F) / s_i, truncated toward zero (raw of a value within 2^-F
//               of p/s); 0 where q_i <= 0 or s_i = 0.
//
// (p_i = A i + B, q_i = C i^2 + D i + E: the host sends p0 = B, dp = A, q0 = E,
// dq0 = C + D, d2q = 2C.) Arithmetic: signed fixed point M.F in W = M + F bits
// (value = raw * 2^-F); the three recurrences are exact W-bit additions unless a
// register overflows (wraps). A quotient of magnitude 2^(W-1) or more is outside
// the format: the unit then outputs +-(2^(W-1) - 1) (no bound covers such a pixel).
// Square root: restoring digit recurrence on the radicand q * 2^F (W - 1 + F bits),
// one root bit per clock, K = ceil((W - 1 + F)/2) clocks (44 at 8.40).
// Divider: restoring, one quotient bit per clock, W - 1 clocks (47 at 8.40), after
// a check that the quotient fits.
// The two are pipelined: the root of pixel i + 1 is taken while pixel i is divided.
// Set-up: B, A, E, C + D and 2C are computed on the host, exactly, and rounded once
// to nearest (`phong-approx setup --method duff`): each is off by at most
// h = 2^-(F+1), the assumption of proofs/Fixed.v.
// Bound: with Ep = h(1 + n), Eq = h(1 + n + n(n-1)/2), r = sqrt(q_min - Eq) (where
// q_min > Eq and r > 2h), every pixel is within
// (Ep + Eq/(2r) + 2h)/(r - 2h) + 2h of the exact Duff value
// (fixed_point_duff_unit_error: the loops' errors, as fixed_point_gouraud_error and
// fixed_point_corrected_euler_error bound them, through fixed_point_duff_error, whose
// hypotheses are the truncated root, in (sqrt(q) - 2^-F, sqrt(q)], and a quotient
// within 2^-F).
// Latency: pixel 0 is valid K + W + 2 cycles after the set-up is taken (94 at
// 8.40). Throughput: one pixel per max(K + 2, W) cycles (48 at 8.40) while out_ready
// is high. in_ready is high again once the span's last pixel has entered the square
// root, so the next span's set-up overlaps the last pixels.
//
// Ports (every unit of harness/hdl has these; docs/conformance.md, "Hardware span
// units"):
//   clk, rst         clock; synchronous reset, active high
//   in_valid/ready   one span's set-up is taken on a cycle with both high
//   in_n             steps n >= 1: the unit emits n + 1 pixels
//   in_p0, in_dp, in_q0, in_dq0, in_d2q   the set-up this unit uses (raw, W bits)
//   in_t0, in_ds     unused here
//   out_valid/ready  one pixel leaves on a cycle with both high; out_ready may stay
//                    low for any number of cycles (the pixel is held)
//   out_value        the pixel (raw, W bits)
//   out_last         high with pixel n
module duff #(
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
    // The common ports this method does not use.
    /* verilator lint_off UNUSEDSIGNAL */
    input  logic signed [M+F-1:0] in_t0,
    input  logic signed [M+F-1:0] in_ds,
    /* verilator lint_on UNUSEDSIGNAL */
    input  logic signed [M+F-1:0] in_q0,
    input  logic signed [M+F-1:0] in_dq0,
    input  logic signed [M+F-1:0] in_d2q,
    output logic                  out_valid,
    input  logic                  out_ready,
    output logic signed [M+F-1:0] out_value,
    output logic                  out_last
);
  localparam int W  = M + F;
  localparam int K  = (W + F) / 2;       // root bits: ceil((W - 1 + F)/2)
  localparam int XB = 2 * K;             // the radicand, padded to whole bit pairs
  localparam int QB = W - 1;             // quotient bits
  localparam int HW = (F + 1 > K) ? F + 1 : K;  // the fit check's width

  // The recurrences.
  logic                a_active;  // pixels of a span are still to enter the root
  logic [15:0]         a_left;    // pixels after the next one to enter
  logic signed [W-1:0] p, dp, q, dq, d2q;

  // The square root, s = floor(sqrt(q * 2^F)).
  typedef enum logic [1:0] {S_IDLE, S_RUN, S_DONE} s_state_t;
  s_state_t            s_state;
  logic [7:0]          s_cnt;     // root bits still to make
  logic [XB-1:0]       s_x;       // the radicand's bit pairs, most significant first
  logic [K:0]          s_rem;     // partial remainder, at most 2 * root
  logic [K-1:0]        s_root;
  logic signed [W-1:0] s_p;       // this pixel's p
  logic                s_last;    // this pixel is pixel n
  logic                s_zero;    // q <= 0: the pixel is 0

  logic [K+2:0] s_rem2, s_trial;
  assign s_rem2  = {s_rem, s_x[XB-1:XB-2]};
  assign s_trial = {1'b0, s_root, 2'b01};

  // The divider, |p| * 2^F / s.
  typedef enum logic [1:0] {D_IDLE, D_RUN, D_DONE} d_state_t;
  d_state_t            d_state;
  logic [7:0]          d_cnt;     // quotient bits still to make
  logic [K-1:0]        d_r;       // partial remainder, below s
  logic [QB-1:0]       d_low;     // the numerator's low bits, most significant first
  logic [QB-1:0]       d_q;       // the quotient's magnitude
  logic [K-1:0]        d_s;
  logic                d_neg;
  logic                d_last;

  logic [K:0] d_r2;
  assign d_r2 = {d_r, d_low[QB-1]};

  // The numerator of the pixel leaving the root: |p| * 2^F = {hi, low}, where
  // hi = |p| * 2^F >> QB; the quotient fits QB bits iff hi < s.
  logic [W-1:0]   p_abs;
  logic [W+F-1:0] num;
  logic [HW-1:0]  num_hi, root_hi;
  assign p_abs   = (s_p < 0) ? W'(-s_p) : W'(s_p);
  assign num     = {p_abs, {F{1'b0}}};
  assign num_hi  = HW'(num[W+F-1:QB]);
  assign root_hi = HW'(s_root);

  logic s_start, d_load;
  assign s_start = a_active && (s_state == S_IDLE);
  assign d_load  = (s_state == S_DONE) &&
                   ((d_state == D_IDLE) || (d_state == D_DONE && out_ready));

  assign in_ready  = !a_active;
  assign out_valid = (d_state == D_DONE);
  assign out_value = d_neg ? -(W'(d_q)) : W'(d_q);
  assign out_last  = d_last;

  // Control (reset).
  always_ff @(posedge clk) begin
    if (rst) begin
      a_active <= 1'b0;
      s_state  <= S_IDLE;
      d_state  <= D_IDLE;
    end else begin
      if (in_valid && in_ready) a_active <= 1'b1;
      else if (s_start && a_left == 16'd0) a_active <= 1'b0;

      if (s_start) s_state <= (q <= 0) ? S_DONE : S_RUN;
      else if (s_state == S_RUN && s_cnt == 8'd1) s_state <= S_DONE;
      else if (d_load) s_state <= S_IDLE;

      if (d_load) begin
        if (s_zero || s_root == '0 || num_hi >= root_hi) d_state <= D_DONE;
        else d_state <= D_RUN;
      end else if (d_state == D_RUN && d_cnt == 8'd1) d_state <= D_DONE;
      else if (d_state == D_DONE && out_ready) d_state <= D_IDLE;
    end
  end

  // Data (loaded before use; not reset).
  always_ff @(posedge clk) begin
    if (in_valid && in_ready) begin
      a_left <= in_n;
      p      <= in_p0;
      dp     <= in_dp;
      q      <= in_q0;
      dq     <= in_dq0;
      d2q    <= in_d2q;
    end else if (s_start) begin
      a_left <= a_left - 16'd1;
      p      <= p + dp;
      q      <= q + dq;
      dq     <= dq + d2q;
    end

    if (s_start) begin
      s_zero <= (q <= 0);
      s_x    <= XB'(q) << F;
      s_rem  <= '0;
      s_root <= '0;
      s_cnt  <= 8'(K);
      s_p    <= p;
      s_last <= (a_left == 16'd0);
    end else if (s_state == S_RUN) begin
      if (s_rem2 >= s_trial) begin
        s_rem  <= (K+1)'(s_rem2 - s_trial);
        s_root <= {s_root[K-2:0], 1'b1};
      end else begin
        s_rem  <= (K+1)'(s_rem2);
        s_root <= {s_root[K-2:0], 1'b0};
      end
      s_x   <= s_x << 2;
      s_cnt <= s_cnt - 8'd1;
    end

    if (d_load) begin
      d_last <= s_last;
      d_neg  <= (s_p < 0);
      d_s    <= s_root;
      d_r    <= K'(num_hi);
      d_low  <= num[QB-1:0];
      d_cnt  <= 8'(QB);
      if (s_zero || s_root == '0) d_q <= '0;
      else if (num_hi >= root_hi) d_q <= '1;  // saturate: the quotient does not fit
      else d_q <= '0;
    end else if (d_state == D_RUN) begin
      if (d_r2 >= {1'b0, d_s}) begin
        d_r <= K'(d_r2 - {1'b0, d_s});
        d_q <= {d_q[QB-2:0], 1'b1};
      end else begin
        d_r <= K'(d_r2);
        d_q <= {d_q[QB-2:0], 1'b0};
      end
      d_low <= d_low << 1;
      d_cnt <= d_cnt - 8'd1;
    end
  end
endmodule
