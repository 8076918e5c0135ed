"""Load-distribution models: the exact ring equilibrium, the continuum model, the classical
approximations, and the registry that runs them side by side."""
