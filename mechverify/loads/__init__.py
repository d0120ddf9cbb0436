"""Loads on a machine: motion profiles and the torque demand they put on a drive train."""
