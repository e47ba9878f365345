#!/usr/bin/env python3
"""Extensions > Pak > Pack: fills a closed shape with deformable copies of objects (`pak pack`)."""
from pak_effect import PakEffect


class PakPack(PakEffect):
    """Runs `pak pack` on the selection and adds the packing as a new layer."""

    command = "pack"
    result_label = "Pak pack"
    helper_layers = ("fixed",)

    def add_pak_arguments(self, pars):
        pars.add_argument("--count", type=int, default=0)
        pars.add_argument("--max_iterations", type=int, default=30000)
        pars.add_argument("--preset", default="default", choices=("default", "soft", "rigid"))
        pars.add_argument("--orientation", default="random", choices=("random", "upright"))

    def pak_arguments(self):
        return ["--count", str(self.options.count), "--max-iterations", str(self.options.max_iterations),
                "--preset", self.options.preset, "--orientation", self.options.orientation]


if __name__ == "__main__":
    PakPack().run()
