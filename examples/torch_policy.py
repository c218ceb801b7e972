"""A small PyTorch policy on the planes form, acting for a whole batch with masked logits.

pip install torch  # CPU wheels are enough
python examples/torch_policy.py
"""

import torch
from torch import nn

import rinshan


class PlanesPolicy(nn.Module):
    """Planes (64 x 34) through a 1-D convolution over tile types, scalars through a linear layer,
    then logits over the action ids."""

    def __init__(self, num_actions: int, planes: int = 64, scalars: int = 48, width: int = 128):
        super().__init__()
        self.conv = nn.Sequential(
            nn.Conv1d(planes, width, 3, padding=1),
            nn.ReLU(),
            nn.Conv1d(width, 32, 3, padding=1),
            nn.ReLU(),
            nn.Flatten(),
        )
        self.scalars = nn.Linear(scalars, 64)
        self.head = nn.Sequential(
            nn.Linear(32 * 34 + 64, width), nn.ReLU(), nn.Linear(width, num_actions)
        )

    def forward(self, planes, scalars, mask):
        x = self.conv(planes.float())
        s = torch.relu(self.scalars(scalars.float() / 100.0))
        logits = self.head(torch.cat([x, s], dim=1))
        # Illegal actions get no probability.
        return logits.masked_fill(~mask, torch.finfo(logits.dtype).min)


def main():
    env = rinshan.make("red", num_envs=256, seed=0, observation=("planes",))
    policy = PlanesPolicy(env.spec.num_actions)
    ts = env.reset()
    games = 0
    with torch.no_grad():
        for _ in range(200):
            # The env's arrays are read-only and rewritten by the next step: the tensors copy
            # them (as a move to a GPU would in any case).
            logits = policy(
                torch.tensor(ts.observation["planes"]),
                torch.tensor(ts.observation["scalars"]),
                torch.tensor(ts.legal_action_mask),
            )
            actions = torch.distributions.Categorical(logits=logits).sample().numpy()
            ts = env.step(actions)
            assert not ts.info["illegal"].any()
            games += int(ts.terminated.sum())
    print(f"200 steps x 256 envs, {games} games finished, no illegal action")


if __name__ == "__main__":
    main()
