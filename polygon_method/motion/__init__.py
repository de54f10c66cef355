"""The motion records the views read: one instant (`solution`: `solve`, `Solution`) and
many (`sweeps`: `sweep`, `SweepResult`), each a `Motion` with its derived quantities and,
where masses are given, its forces."""
