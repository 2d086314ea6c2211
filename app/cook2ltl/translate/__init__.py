"""Stage 5 of Algorithm 1: LTL formulas from reduced actions (formula), and their JSON form (serialize)."""
