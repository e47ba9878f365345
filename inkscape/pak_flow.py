#!/usr/bin/env python3
"""Extensions > Pak > Flow: fills a closed shape with elements bent along the strokes of the
`guides` layer (`pak flow`)."""
from pak_effect import PakEffect
from pak_inkex import inkex


class PakFlow(PakEffect):
    """Runs `pak flow` on the selection and the guides, and adds the packing as a new layer."""

    command = "flow"
    result_label = "Pak flow"
    helper_layers = ("guides", "spines", "fixed")
    required_layers = {
        "guides": "Pak: Flow follows direction strokes: draw one or more in a layer named 'guides' "
                  "(each container needs one; the flow runs the way the stroke is drawn)."}

    def add_pak_arguments(self, pars):
        pars.add_argument("--count", type=int, default=100)
        pars.add_argument("--iterations", type=int, default=15)
        pars.add_argument("--spacing", default="")
        pars.add_argument("--fill_gaps", type=inkex.Boolean, default=False)
        pars.add_argument("--mirror", default="")

    def pak_arguments(self):
        arguments = ["--count", str(self.options.count), "--iterations", str(self.options.iterations)]
        if self.options.spacing.strip():
            arguments += ["--spacing", self.options.spacing.strip()]
        if self.options.fill_gaps:
            arguments.append("--fill-gaps")
        if self.options.mirror.strip():
            arguments += ["--mirror", self.options.mirror.strip()]
        return arguments


if __name__ == "__main__":
    PakFlow().run()
