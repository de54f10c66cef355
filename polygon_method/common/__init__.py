"""The floor of the house: the one error family (`errors`), units and how a quantity string
is read (`units`), how a number is written (`numbers`). Everything else may import these;
they import nothing of the package above them."""
