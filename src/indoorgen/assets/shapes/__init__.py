"""Shared mesh parts every generator family builds from: primitives, sweeps (lofts, tubes), planar
outlines, frames and legs, mesh builders, moving parts, surfaces and collision pieces."""
