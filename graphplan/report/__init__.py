"""Reports: results.json now; tables and the explanatory note as they come."""
