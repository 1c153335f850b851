"""What a plan starts from: the requirements and the plan's settings (resolved once into
the values every caller takes), the column lists of every table, and the time budget's clock.

May import nothing else of the pipeline.
"""
