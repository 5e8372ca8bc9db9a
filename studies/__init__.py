"""Studies on top of the physics: sweeps, serve what-ifs, the paper reproduced, plots, CLI."""
