"""junctionart: procedural OpenDRIVE road networks after the JunctionArt paper."""
