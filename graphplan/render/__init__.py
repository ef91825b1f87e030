"""Drawings: layouts turn records into primitives, the svg backend writes them."""
