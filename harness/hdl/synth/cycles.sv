// SPDX-License-Identifier: MIT OR Apache-2.0
//
// Cycle counts of one span unit, for harness/hdl/synth/cost.sh (Icarus Verilog):
//
//   iverilog -g2012 -DCOST_UNIT=gouraud -Pcost_cycles.M=8 -Pcost_cycles.F=40 \
//     -o cycles harness/hdl/synth/cycles.sv harness/hdl/units/gouraud.sv
//   vvp -n cycles +n=8
//
// Four spans of n steps each are offered back to back (in_valid high from the end of
// reset until the fourth set-up is taken) and out_ready stays high, so the unit runs
// at its own pace. The set-up is p0 = 1/2, q0 = 1, every slope 0: each unit takes its
// full path (Duff's root and divider make every bit; q <= 0, a zero root or a quotient
// that does not fit would take shorter ones). Prints one line,
//
//   cycles: latency L single S period P
//
//   L  cycles from the set-up taken to pixel 0 valid (taken on cycle c, valid on c + L)
//   S  the first span alone: from the cycle its set-up is taken to the cycle pixel n
//      leaves, both counted
//   P  in the stream: cycles between the last pixels of the third and fourth spans
//      (checked equal to the second and third's; a unit that overlaps the next set-up
//      with the last pixels has P < S)
module cost_cycles #(
    parameter int M = 8,
    parameter int F = 40
);
  localparam int W = M + F;
  localparam int SPANS = 4;

  logic                  clk = 1'b0;
  logic                  rst = 1'b1;
  logic                  in_valid = 1'b0;
  logic                  in_ready;
  logic [15:0]           in_n;
  logic signed [W-1:0]   in_p0, in_dp, in_t0, in_ds, in_q0, in_dq0, in_d2q;
  logic                  out_valid;
  logic                  out_ready = 1'b1;
  logic signed [W-1:0]   out_value;
  logic                  out_last;

  `COST_UNIT #(
      .M(M),
      .F(F)
  ) unit (
      .clk      (clk),
      .rst      (rst),
      .in_valid (in_valid),
      .in_ready (in_ready),
      .in_n     (in_n),
      .in_p0    (in_p0),
      .in_dp    (in_dp),
      .in_t0    (in_t0),
      .in_ds    (in_ds),
      .in_q0    (in_q0),
      .in_dq0   (in_dq0),
      .in_d2q   (in_d2q),
      .out_valid(out_valid),
      .out_ready(out_ready),
      .out_value(out_value),
      .out_last (out_last)
  );

  integer n, cycle, taken, valid0, last_count, pixels, i;
  integer taken_at[0:SPANS-1];
  integer last_at[0:SPANS-1];

  initial begin
    if (!$value$plusargs("n=%d", n)) n = 8;
    in_n   = 16'(n);
    in_p0  = W'(1) <<< (F - 1);
    in_dp  = '0;
    in_t0  = '0;
    in_ds  = '0;
    in_q0  = W'(1) <<< F;
    in_dq0 = '0;
    in_d2q = '0;
    cycle = 0;
    taken = 0;
    valid0 = -1;
    last_count = 0;
    pixels = 0;
    // Reset: four cycles.
    for (i = 0; i < 4; i = i + 1) begin
      #1 clk = 1'b1;
      #1 clk = 1'b0;
    end
    rst = 1'b0;
    in_valid = 1'b1;
    while (last_count < SPANS) begin
      #1;  // inputs settled, clk low: sample this cycle's handshakes
      if (in_valid && in_ready) begin
        taken_at[taken] = cycle;
        taken = taken + 1;
      end
      if (out_valid && valid0 < 0) valid0 = cycle;
      if (out_valid && out_ready) begin
        pixels = pixels + 1;
        if (out_last) begin
          last_at[last_count] = cycle;
          last_count = last_count + 1;
        end
      end
      clk = 1'b1;
      #1 clk = 1'b0;
      if (taken == SPANS) in_valid = 1'b0;
      cycle = cycle + 1;
      if (cycle > 1000000) begin
        $display("cycles: error: no fourth out_last within 1000000 cycles");
        $finish;
      end
    end
    if (pixels != SPANS * (n + 1)) begin
      $display("cycles: error: %0d pixels for %0d spans of n = %0d", pixels, SPANS, n);
    end else if (last_at[3] - last_at[2] != last_at[2] - last_at[1]) begin
      $display("cycles: error: the stream has no steady period (%0d, %0d)",
               last_at[2] - last_at[1], last_at[3] - last_at[2]);
    end else begin
      $display("cycles: latency %0d single %0d period %0d", valid0 - taken_at[0],
               last_at[0] - taken_at[0] + 1, last_at[3] - last_at[2]);
    end
    $finish;
  end
endmodule
