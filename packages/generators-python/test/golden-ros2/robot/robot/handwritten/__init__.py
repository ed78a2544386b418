"""Generated package."""
