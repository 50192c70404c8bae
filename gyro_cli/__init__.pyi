# Types of the names gyro_cli/__init__.py loads on first use.
from .api import Answer as Answer
from .api import CheckReport as CheckReport
from .api import Result as Result
from .api import Sweep as Sweep
from .api import check as check
from .api import check_files as check_files
from .api import kinds as kinds  # at run time the registry module, callable
from .api import load as load
from .api import registry as registry
from .api import solve as solve
from .api import solve_file as solve_file
from .api import sweep as sweep
from .core.errors import InputError as InputError

__version__: str
__all__: list[str]
