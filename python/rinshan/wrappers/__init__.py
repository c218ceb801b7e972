"""Adapters to the common RL interfaces: `gymnasium` (single game and vector env, self-play
view) and `pettingzoo` (AEC, one game). Each imports its library only when used."""
