"""The one exception the package raises for anything the component or the caller got wrong."""


class PeriStepError(RuntimeError):
    """A refused call or an invalid request.

    ``messages`` holds what the component logged (status Error or Warning) during the failing call;
    ``str(error)`` names the call and joins those messages.
    """

    def __init__(self, text, messages=()):
        self.messages = list(messages)
        if self.messages:
            text = f"{text}: {'; '.join(self.messages)}"
        super().__init__(text)
