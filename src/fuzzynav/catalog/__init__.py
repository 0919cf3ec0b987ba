"""The name tables of the command line, at the top of the package so no table sits below what it names.

- :mod:`.controllers` — ``--controller NAME`` → a controller factory;
- :mod:`.tasks` — ``fuzzynav train TASK`` → a training function of :mod:`fuzzynav.learn.tasks`,
  and a model file's ``kind`` → the loader that rebuilds its controller (``--model FILE``);
- :mod:`.experiments` — ``fuzzynav reproduce ID`` → a thesis figure or table.

Entries are ``"module:attribute"`` strings resolved by :func:`fuzzynav.lookup.resolve` when used,
so listing names imports nothing heavy. Modules below this package never name it.
"""
