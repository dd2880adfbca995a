"""What the toolkit shows: LaTeX derivations (:mod:`.latex`) and matplotlib figures (:mod:`.plotting`)."""
