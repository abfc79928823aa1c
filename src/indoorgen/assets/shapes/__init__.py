"""Shared mesh parts every generator family builds from: primitives, frames and legs, mesh builders, moving parts and collision pieces."""
