"""Motion: motion profiles (x, v, a, j over time) and the torque demand they put on a drive train."""
