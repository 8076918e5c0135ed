"""Contact mechanics: Hertz point contact of balls, line contact of rollers."""
