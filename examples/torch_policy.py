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


def main(num_envs: int = 64, max_steps: int = 5000):
    env = rinshan.make("red", num_envs=num_envs, seed=0, observation=("planes",))
    policy = PlanesPolicy(env.spec.num_actions)
    ts = env.reset()
    games = steps = 0
    # Until as many games have ended as there are envs: a half game (East and South) is several
    # hundred decisions, so a fixed 200 steps ended none.
    with torch.no_grad():
        while games < num_envs and steps < max_steps:
            # The env's arrays are read-only and rewritten by the next step: the tensors copy
            # them (as a move to a GPU would in any case).
            logits = policy(
                torch.tensor(ts.observation["planes"]),
                torch.tensor(ts.observation["scalars"]),
                torch.tensor(ts.legal_action_mask),
            )
            actions = torch.distributions.Categorical(logits=logits).sample().numpy()
            ts = env.step(actions)
            steps += 1
            assert not ts.info["illegal"].any()
            games += int(ts.terminated.sum())
    env.close()
    print(f"{steps} steps x {num_envs} envs, {games} games finished, no illegal action")
    return games


if __name__ == "__main__":
    main()
