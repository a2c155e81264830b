"""The papers' case studies as reproducible, seeded runs with reports."""
