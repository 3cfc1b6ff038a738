// SPDX-License-Identifier: MIT OR Apache-2.0
//
// The testbench's top: the common ports, with their documented widths, connected
// by name to the unit under test (its module name is `PHONG_HDL_UNIT, given by
// run.sh). A unit whose ports or parameters differ from these fails here.
module phong_hdl_top #(
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
    input  logic signed [M+F-1:0] in_q0,
    input  logic signed [M+F-1:0] in_dq0,
    input  logic signed [M+F-1:0] in_d2q,
    output logic                  out_valid,
    input  logic                  out_ready,
    output logic signed [M+F-1:0] out_value,
    output logic                  out_last
);
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
endmodule
