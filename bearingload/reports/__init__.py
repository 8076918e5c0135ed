"""Output: the one renderer, the table of quantities, and the reports built from them."""
