"""gyro: worked answers to textbook problems of gyroscopic motion (Chapter 11)."""

__version__ = "0.1.0"
