// SPDX-License-Identifier: MIT OR Apache-2.0
//
// The four-state check of harness/hdl (Icarus Verilog): Verilator, which builds the
// model run.sh judges, has two states only, and turns Z into 0. This testbench drives
// the first spans of a set through the unit in four-state simulation and reports the
// first cycle on which in_ready or out_valid, or with out_valid out_value or
// out_last, has an X or Z bit.
//
//   iverilog -g2012 -DPHONG_HDL_UNIT=<module> -Pphong_hdl_xz.M=<M> -Pphong_hdl_xz.F=<F>
//            -o xz tb/xz.sv UNIT.sv
//   vvp -n xz +stimulus=FILE
//
// FILE: one span a line, `case n p0 dp t0 ds q0 dq0 d2q` (raw decimal integers, as
// `phong-approx setup` prints them; run.sh writes it). Output: one line, `xz: ok: ...`
// or `xz: case C, cycle K: ...` (then run.sh exits 2).
`timescale 1ns / 1ps
module phong_hdl_xz #(
    parameter int M = 8,
    parameter int F = 40
);
  localparam int W = M + F;

  logic                clk = 1'b0;
  logic                rst = 1'b1;
  logic                in_valid = 1'b0;
  logic                in_ready;
  logic [15:0]         in_n = '0;
  logic signed [W-1:0] in_p0 = '0, in_dp = '0, in_t0 = '0, in_ds = '0;
  logic signed [W-1:0] in_q0 = '0, in_dq0 = '0, in_d2q = '0;
  logic                out_valid;
  logic                out_ready = 1'b0;
  logic signed [W-1:0] out_value;
  logic                out_last;

  `PHONG_HDL_UNIT #(
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

  integer fd, got, cycle, pixels, cases, since, seed;
  reg [8*64-1:0] id;
  reg signed [63:0] n, p0, dp, t0, ds, q0, dq0, d2q;
  reg [8*256-1:0] path;
  reg done_span, offered;

  task automatic fail(input [8*200-1:0] what);
    begin
      $display("xz: case %0s, cycle %0d: %0s", id, cycle, what);
      $finish;
    end
  endtask

  // One cycle: inputs set while clk is low, outputs sampled before the rising edge.
  task automatic step;
    begin
      #1;
      if (!rst && (^in_ready) === 1'bx) fail("in_ready is X or Z");
      if (!rst && (^out_valid) === 1'bx) fail("out_valid is X or Z");
      if (!rst && out_valid === 1'b1) begin
        if ((^out_value) === 1'bx) fail("out_value is X or Z while out_valid is high");
        if ((^out_last) === 1'bx) fail("out_last is X or Z while out_valid is high");
      end
      if (offered && in_ready === 1'b1) begin
        offered = 1'b0;
        since = 0;
      end
      if (out_valid === 1'b1 && out_ready === 1'b1) begin
        pixels = pixels + 1;
        since = 0;
        if (out_last === 1'b1) done_span = 1'b1;
      end
      #4 clk = 1'b1;
      #5 clk = 1'b0;
      cycle = cycle + 1;
      since = since + 1;
      if (since > 4096 + 64 * W) fail("no handshake within the cycle limit");
      if (!offered) in_valid = 1'b0;
      out_ready = ($random(seed) & 3) != 0;
    end
  endtask

  initial begin
    seed = 1;
    cycle = 0;
    pixels = 0;
    cases = 0;
    since = 0;
    offered = 1'b0;
    id = "(reset)";
    if (!$value$plusargs("stimulus=%s", path)) begin
      $display("xz: no +stimulus=FILE");
      $finish;
    end
    fd = $fopen(path, "r");
    if (fd == 0) begin
      $display("xz: cannot open the stimulus");
      $finish;
    end
    repeat (4) step();
    rst = 1'b0;
    forever begin
      got = $fscanf(fd, "%s %d %d %d %d %d %d %d %d\n", id, n, p0, dp, t0, ds, q0, dq0, d2q);
      if (got != 9) begin
        $display("xz: ok: %0d spans, %0d pixels, %0d cycles, no X or Z on the outputs", cases, pixels, cycle);
        $finish;
      end
      in_n = n[15:0];
      in_p0 = p0[W-1:0];
      in_dp = dp[W-1:0];
      in_t0 = t0[W-1:0];
      in_ds = ds[W-1:0];
      in_q0 = q0[W-1:0];
      in_dq0 = dq0[W-1:0];
      in_d2q = d2q[W-1:0];
      in_valid = 1'b1;
      offered = 1'b1;
      done_span = 1'b0;
      while (!done_span) step();
      cases = cases + 1;
    end
  end
endmodule
