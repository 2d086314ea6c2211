"""Stage 5 of Algorithm 1: LTL formulas from reduced actions (sequenced visit, ∧ ∨ ¬ 𝒰)."""
