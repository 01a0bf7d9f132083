:- module(oro_protocol,
          [ oro_reader/3,               % +In, -Reader, +Options
            oro_read_request/3,         % +Reader0, -Request, -Reader
            oro_reader_pending/1,       % +Reader
            oro_drain_input/3,          % +In, +MaxBytes, +Seconds
            oro_write_ok/2,             % +Out, +Value
            oro_write_error/3,          % +Out, +ExceptionName, +Message
            oro_write_event/3,          % +Out, +WatcherId, +Content
            oro_write_closing/1,        % +Out
            oro_encode_value/2,         % +Value, -String
            oro_encode_string/2         % +Text, -Quoted
          ]).
:- use_module(library(error)).
:- use_module(library(option)).
:- use_module(library(debug)).
:- use_module(library(lists)).
:- use_module(library(memfile)).

/** <module> ORO wire protocol: request framing and response encoding

This module is the wire layer of the ORO socket protocol (ORO-SPEC §1
and §3).  It frames requests read from a client and encodes the
messages the server writes back.  It knows nothing about the knowledge
base: `close` is an ordinary request whose lowercased method is `close`
and dispatch is the caller's business.

## Reading requests

A request is a method line, one line per parameter and the 5-character
terminator `#end#` (ORO-SPEC §1.2).  oro_read_request/3 (with a reader
made by oro_reader/3) implements the spec together with its
*Recommendations*:

  - `\r\n` and a lone `\r` count as `\n`.
  - The request is everything before the first `#end#`, which need not
    be on its own line (`add\n[a b c]#end#`).  One `\n` (or `\r\n`)
    right after `#end#` belongs to the terminator; anything else after
    it starts the next request, so pipelined requests are returned in
    order by successive calls.
  - The text is split on `\n`; trailing empty lines are dropped,
    embedded ones are kept (`find\nx\n\n[..]` has 3 parameters), empty
    lines before the method name are ignored.  A request made of empty
    lines only is discarded silently; a bare `#end#` is
    request("", []).
  - A first line that is `help` (case-insensitive, trailing white space
    ignored) is returned as `help` at once, without waiting for
    `#end#`; if the next non-empty line is `#end#` it is swallowed, so
    `help\n#end#\n` gives one `help`.

**Bytes, not characters.**  The reader switches the input stream to
`octet` and decodes UTF-8 itself.  SWI-Prolog's own UTF-8
decoder cannot be used to detect bad input: it prints a warning and
substitutes U+FFFD for an illegal start byte and silently accepts
overlong forms.  Our decoder is strict (no overlong forms, no
surrogates, nothing above U+10FFFF, no truncated sequences); a request
with invalid UTF-8 is skipped up to its `#end#` and reported as
bad(encoding), after which the connection is in sync again.  NUL bytes
are ordinary characters.  (A memory stream from open_string/2, whose
encoding cannot be changed, is read as characters and re-encoded.)

**Speed and bounded memory.**  The stream is read in blocks of
whatever is available (fill_buffer/1, read_pending_codes/3) and all
per-byte work (finding line ends and `#end#`, decoding) is done by C
builtins (about 0.1 s per MB of ASCII).  The bytes of a request
are counted as they are read (line terminators and `#end#` included).
As soon as the count exceeds the `max_request_size` option the reader
returns bad(too_large(Limit)) *without reading further*: the rest of
that request is still unread, so the connection is out of sync and the
caller must answer with an error and close it.  Long lines are decoded
in 64 KiB chunks, so memory stays around the limit even for lines of
many megabytes.

The usual case takes fast paths that give what the general code gives
(test/test_parse.pl compares them): a block that is exactly one whole
request is split into its lines at once, a block without `\r` or NUL is cut
with one split_string/4, a whole line found in one block (or a bare
`#end#`) is returned at once, and a list of strings none of which needs
escaping is encoded in one piece.

**State between calls.**  A block may hold more than one request
(pipelining), and two facts must survive from one call to the next
without waiting for the peer: "a `\n` right now would end the previous
`#end#` (or `\r`)" and "the previous request was a bare `help` line".
The reader term carries them, with the bytes read but not consumed:
each call takes a reader and returns the next one, so the state of a
connection lives in its serving loop.  Do not use wait_for_input/3 on
the stream to decide whether a request is pending (a pipelined request
may already be in the reader); use a stream timeout
(`set_stream(In, timeout(Seconds))`) for the keep-alive of ORO-SPEC
§1.5.

I/O errors (a peer reset, a stream timeout) are raised as usual; the
request being read is then lost and the caller should close the
connection.

## Writing messages

The writers build each complete message in memory and emit it with one
write followed by one flush.  Events (§1.4) may be pushed by other
threads on the same stream: the caller must hold the connection's
mutex around every writer call so messages never interleave.  The
output stream must be set to `encoding(utf8)` by the caller.

Values (§3) are encoded by oro_encode_value/2, which defines the
escaping once for replies and events: no value line holds a raw line
break (so none can read as `#end#`), and both real clients (liboro's
Boost tokeniser, pyoro's eval()) read every list and map element back;
plain string replies read as oro-server 0.8.2's did.  The rules, and
the two characters no escape can carry to both clients (CR and NUL),
are documented there.  multiline_string/1 exists for `help`, whose text
keeps its raw newlines.
*/

:- predicate_options(oro_reader/3, 3,
                     [ max_request_size(positive_integer),
                       max_lines(nonneg)
                     ]).

default_max_request_size(16777216).    % 16 MiB

chunk_size(65536).                      % bytes decoded at once in long lines


                 /*******************************
                 *            READING           *
                 *******************************/

%!  oro_reader(+In, -Reader, +Options) is det.
%
%   Reader reads requests from the input stream In, which it owns from
%   now on: In is switched to `octet` (a stream whose encoding cannot
%   change, such as one from open_string/2, is read as characters and
%   re-encoded).  Options:
%
%     - max_request_size(+Bytes)
%       Maximum size of one request in bytes (default 16 MiB).
%     - max_lines(+N)
%       Maximum number of lines of one request, the method's and empty
%       ones included (default 0: no limit).  Past it the rest of the
%       request is skipped up to its `#end#` by a search of its bytes
%       (no line is read), and the request is bad(too_many_lines(N)):
%       16 MB of empty lines cost 43 s of CPU and 2 GB read line by
%       line.

oro_reader(In, oro_reader(In, Limit, source(In, Mode, MaxLines),
                          state(none, false, [])), Options) :-
    must_be(list, Options),
    default_max_request_size(Default),
    option(max_request_size(Limit), Options, Default),
    must_be(positive_integer, Limit),
    option(max_lines(MaxLines), Options, 0),
    must_be(nonneg, MaxLines),
    must_be_input_stream(In),
    stream_property(In, encoding(Encoding)),
    byte_mode(In, Encoding, Mode).

%!  oro_read_request(+Reader0, -Request, -Reader) is det.
%
%   Read the next request with Reader0; Reader is the reader to use
%   for the next one (it holds the bytes read past this request).
%   Request is one of
%
%     - request(MethodName, Params)
%       MethodName is a string, verbatim from the first non-empty line
%       (not trimmed, not lowercased); Params is a list of strings, one
%       per line.
%     - help
%       The first line was `help`; see the module documentation.
%     - end_of_file
%       The peer closed the connection; a partial request is dropped.
%     - bad(too_large(Limit))
%       The request exceeds Limit bytes.  The stream is out of sync:
%       answer with an error and close the connection.
%     - bad(encoding)
%       The request is not valid UTF-8.  It has been skipped up to its
%       `#end#`; the connection can continue.
%     - bad(too_many_lines(N))
%       The request has more than N lines (option max_lines).  It has
%       been skipped up to its `#end#`; the connection can continue.
%
%   I/O errors are not caught.

oro_read_request(oro_reader(In, Limit, Source, State0), Request,
                 oro_reader(In, Limit, Source, State)) :-
    request(Source, Limit, State0, Request, State1),
    (   final_request(Request)
    ->  State = state(none, false, [])
    ;   State = State1
    ),
    debug_request(Request).

%!  oro_reader_pending(+Reader) is semidet.
%
%   True if more input is there for Reader right now: bytes it has read
%   but not returned yet, bytes waiting on its stream, or the end of
%   its input.  Does not block.  (The server prepares the next request
%   of a client that sends them back to back while it answers the
%   previous one.)

oro_reader_pending(oro_reader(In, _, _, state(_, _, Tokens))) :-
    (   Tokens \== []
    ->  true
    ;   catch(wait_for_input([In], [_], 0), _, fail)
    ).

%!  oro_drain_input(+In, +MaxBytes, +Seconds) is det.
%
%   Read and discard what the peer still sends on In, up to MaxBytes or
%   until nothing arrives for Seconds, or end of file.  Used before
%   closing a connection whose stream is out of sync (a request too
%   large), so the peer is not reset before it reads our error.

oro_drain_input(In, MaxBytes, Seconds) :-
    must_be(nonneg, MaxBytes),
    must_be(number, Seconds),
    catch(( set_stream(In, timeout(Seconds)),
            drain(In, MaxBytes)
          ),
          _, true).

drain(In, Budget) :-
    (   Budget =< 0
    ->  true
    ;   fill_buffer(In),
        read_pending_codes(In, Codes, []),
        length(Codes, N),
        (   N =:= 0
        ->  true
        ;   Budget1 is Budget - N,
            drain(In, Budget1)
        )
    ).

must_be_input_stream(In) :-
    (   var(In)
    ->  instantiation_error(In)
    ;   is_stream(In)
    ->  (   stream_property(In, input)
        ->  true
        ;   permission_error(input, stream, In)
        )
    ;   existence_error(stream, In)
    ).

%   byte_mode(+In, +Encoding, -Mode)
%
%   Switch In to octet.  Mode is `bytes`, or `text` for a stream whose
%   encoding cannot be changed (a memory stream from open_string/2):
%   its characters are then re-encoded as UTF-8 bytes, see fill/2.

byte_mode(In, Encoding, Mode) :-
    (   Encoding == octet
    ->  Mode = bytes
    ;   catch(set_stream(In, encoding(octet)),
              error(permission_error(_, _, _), _),
              fail)
    ->  Mode = bytes
    ;   Mode = text
    ).

debug_request(request(Method, Params)) :-
    !,
    length(Params, Arity),
    debug(oro(protocol), 'request ~q with ~D parameter(s)', [Method, Arity]).
debug_request(Request) :-
    debug(oro(protocol), 'request ~q', [Request]).


%   The reader's state between calls: state(Skip, Help, Tokens)
%
%     - Skip: what the next bytes may begin with that must be skipped
%         - none: nothing
%         - lf:   the previous line ended with `\r`; skip one `\n`
%         - eol:  the previous request ended with `#end#`; skip one
%                 `\n`, or `\r` and a `\n` after it
%     - Help: `true` after a `help` line returned before its `#end#`
%     - Tokens: tokens read from the stream but not consumed yet (see
%       fill/2)

final_request(end_of_file).
final_request(bad(too_large(_))).


%!  request(+In, +Limit, +State0, -Request, -State) is det.
%
%   Read one request.  Empty lines before the method are skipped
%   (Blank records that some were seen, to tell a discarded empty
%   request from a bare `#end#`).

request(In, Limit, state(Skip0, Help0, Tokens0), Request, State) :-
    In = source(_, _, MaxLines),
    (   MaxLines > 0
    ->  Lines is MaxLines + 1
    ;   Lines = 0
    ),
    Budget = b(Limit, Lines),
    (   Tokens0 == [],
        Help0 == false,
        Skip0 \== lf
    ->  read_block(In, Block),
        (   whole_request(Block, Limit, MaxLines, Request0)
        ->  Request = Request0,
            State = state(none, false, [])
        ;   cut_block(Block, Tokens1),
            request_start(In, Limit, Budget, Skip0, false, false, Tokens1,
                          Request, State)
        )
    ;   request_start(In, Limit, Budget, Skip0, Help0, false, Tokens0,
                      Request, State)
    ).



%!  whole_request(+Block, +Limit, -Request) is semidet.
%
%   The usual case, decided from one block read at the start of a
%   request: Block is exactly one request of valid UTF-8 whose first
%   line is a method (not empty, not `help`), ending with the only
%   `#end#` it has (in any case), on a line of its own, and the `\n`
%   after it; no `\r`, no NUL, at most Limit bytes.  Request is what
%   request_start/9 gives for the same bytes (test/test_parse.pl
%   compares them); anything else fails and goes the general way.

whole_request(Block, Limit, Request) :-
    whole_request(Block, Limit, 0, Request).

%   whole_request(+Block, +Limit, +MaxLines, -Request): as
%   whole_request/3, for a block of at most MaxLines lines (0: any
%   number).

whole_request(Block, Limit, MaxLines, request(Method, Params)) :-
    string_length(Block, Length),
    Length =< Limit,
    sub_string(Block, Before, 7, 0, "\n#end#\n"),
    sub_atom_icasechk(Block, End, "#end#"),
    End =:= Before + 1,
    plain_block(Block),
    utf8_decode(Block, Text),
    split_string(Text, "\n", "", [Method|Lines]),
    Method \== "",
    \+ help_line(Method),
    append(Params0, ["#end#", ""], Lines),
    !,
    (   MaxLines =:= 0
    ->  true
    ;   length(Lines, N),                   % Params0, the #end# line
        N =< MaxLines                       % and the method's
    ),
    reverse(Params0, Reversed0),
    drop_empty_lines(Reversed0, Reversed),
    reverse(Reversed, Params).

%   The Budget of the request is b(Bytes, Lines): the bytes it may
%   still have, and Lines is one more than the lines it may still have
%   (counting down from max_lines + 1; from 0, never reaching 1, for no
%   limit).

request_start(In, Limit, b(Bytes, Lines), Skip0, Help0, Blank, Tokens0,
              Request, State) :-
    (   Lines =:= 1
    ->  skip_request(In, Limit, Bytes, Tokens0, Request, State)
    ;   read_line(In, Bytes, Skip0, Tokens0, Line, Term, Used, Skip1, Tokens1),
        Bytes1 is Bytes - Used,
        Lines1 is Lines - 1,
        start_line(Term, Line, In, Limit, b(Bytes1, Lines1), Skip1, Help0,
                   Blank, Tokens1, Request, State)
    ).

start_line(too_large, _, _, Limit, _, _, _, _, _,
           bad(too_large(Limit)), state(none, false, [])) :- !.
start_line(eof, _, _, _, _, _, _, _, _,
           end_of_file, state(none, false, [])) :- !.
start_line(Term, invalid, In, Limit, Budget, Skip1, _, _, Tokens1,
           Request, State) :-
    !,
    resync(Term, In, Limit, Budget, Skip1, Tokens1, Request, State).
start_line(nl, "", In, Limit, Budget, Skip1, Help0, _, Tokens1,
           Request, State) :-
    !,
    request_start(In, Limit, Budget, Skip1, Help0, true, Tokens1,
                  Request, State).
start_line(end, "", In, Limit, _, Skip1, Help0, Blank, Tokens1,
           Request, State) :-
    !,
    (   Help0 == true
    ->  debug(oro(protocol), 'swallowed the #end# of help', []),
        request(In, Limit, state(Skip1, false, Tokens1), Request, State)
    ;   Blank == true
    ->  debug(oro(protocol), 'discarded a request of empty lines', []),
        request(In, Limit, state(Skip1, false, Tokens1), Request, State)
    ;   Request = request("", []),
        State = state(Skip1, false, Tokens1)
    ).
start_line(Term, Method, In, Limit, Budget, Skip1, _, _, Tokens1,
           Request, State) :-
    (   help_line(Method)
    ->  Request = help,
        (   Term == nl
        ->  State = state(Skip1, true, Tokens1)
        ;   State = state(Skip1, false, Tokens1)
        )
    ;   Term == end
    ->  Request = request(Method, []),
        State = state(Skip1, false, Tokens1)
    ;   request_body(In, Limit, Budget, Skip1, Tokens1, Method, [],
                     Request, State)
    ).

request_body(In, Limit, b(Bytes, Lines), Skip0, Tokens0, Method, RevParams,
             Request, State) :-
    (   Lines =:= 1
    ->  skip_request(In, Limit, Bytes, Tokens0, Request, State)
    ;   read_line(In, Bytes, Skip0, Tokens0, Line, Term, Used, Skip1, Tokens1),
        Bytes1 is Bytes - Used,
        Lines1 is Lines - 1,
        body_line(Term, Line, In, Limit, b(Bytes1, Lines1), Skip1, Tokens1,
                  Method, RevParams, Request, State)
    ).

body_line(too_large, _, _, Limit, _, _, _, _, _,
          bad(too_large(Limit)), state(none, false, [])) :- !.
body_line(eof, _, _, _, _, _, _, _, _,
          end_of_file, state(none, false, [])) :- !.
body_line(Term, invalid, In, Limit, Budget, Skip1, Tokens1, _, _,
          Request, State) :-
    !,
    resync(Term, In, Limit, Budget, Skip1, Tokens1, Request, State).
body_line(nl, Line, In, Limit, Budget, Skip1, Tokens1, Method, RevParams,
          Request, State) :-
    !,
    request_body(In, Limit, Budget, Skip1, Tokens1, Method, [Line|RevParams],
                 Request, State).
body_line(end, Line, _, _, _, Skip1, Tokens1, Method, RevParams,
          request(Method, Params), state(Skip1, false, Tokens1)) :-
    drop_empty_lines([Line|RevParams], RevParams1),
    reverse(RevParams1, Params).

drop_empty_lines([""|T0], T) :-
    !,
    drop_empty_lines(T0, T).
drop_empty_lines(T, T).

%!  resync(+Term, +In, +Limit, +Budget, +Skip0, +Tokens0,
%!         -Request, -State) is det.
%
%   The current request has invalid UTF-8.  Skip its lines up to its
%   `#end#`; Term is how the offending line ended.

resync(end, _, _, _, Skip, Tokens, bad(encoding), state(Skip, false, Tokens)) :- !.
resync(too_large, _, Limit, _, _, _,
       bad(too_large(Limit)), state(none, false, [])) :- !.
resync(eof, _, _, _, _, _, end_of_file, state(none, false, [])) :- !.
resync(nl, In, Limit, b(Bytes, Lines), Skip0, Tokens0, Request, State) :-
    skip_line(In, Bytes, Skip0, Tokens0, Term, Used, Skip1, Tokens1),
    Bytes1 is Bytes - Used,
    resync(Term, In, Limit, b(Bytes1, Lines), Skip1, Tokens1, Request, State).

%!  skip_request(+In, +Limit, +Bytes, +Tokens0, -Request, -State) is det.
%
%   The current request has more lines than max_lines: skip the rest of
%   it (Tokens0, then blocks read from In) up to its `#end#`, searching
%   the bytes for it rather than reading lines.  Request is
%   bad(too_many_lines(Max)), or what ends the connection: the request
%   grew past Bytes more bytes, or the peer left.  (Its remaining lines
%   are not checked for UTF-8: it is refused anyway.)

skip_request(In, Limit, Bytes, Tokens0, Request, State) :-
    In = source(_, _, Max),
    maplist(token_text, Tokens0, Texts),
    atomics_to_string(Texts, Text),
    skip_text(Text, "", In, Limit, Bytes, bad(too_many_lines(Max)),
              Request, State).

token_text(text(Text), Text).
token_text(nl, "\n").
token_text(cr, "\r").

%   skip_text(+Text, +Tail, +In, +Limit, +Bytes, +Bad, -Request, -State):
%   Text follows Tail, the last bytes skipped (where a `#end#` split
%   between two blocks may start).

skip_text(Text, Tail0, In, Limit, Bytes, Bad, Request, State) :-
    string_concat(Tail0, Text, Window),
    string_length(Text, Length),
    string_length(Tail0, TailLength),
    (   end_marker(Window, Offset)
    ->  RestAt is Offset + 5,
        Used is RestAt - TailLength,
        (   Used > Bytes
        ->  Request = bad(too_large(Limit)),
            State = state(none, false, [])
        ;   sub_string(Window, RestAt, _, 0, Rest),
            cut_block(Rest, Tokens),
            Request = Bad,
            State = state(eol, false, Tokens)
        )
    ;   Bytes1 is Bytes - Length,
        (   Bytes1 < 0
        ->  Request = bad(too_large(Limit)),
            State = state(none, false, [])
        ;   read_block(In, Block),
            (   Block == ""
            ->  Request = end_of_file,
                State = state(none, false, [])
            ;   last_bytes(Window, Tail),
                skip_text(Block, Tail, In, Limit, Bytes1, Bad, Request, State)
            )
        )
    ).

help_line(Line) :-
    sub_string(Line, 0, 4, After, Help),
    string_lower(Help, "help"),
    sub_string(Line, 4, After, 0, Rest),
    string_codes(Rest, Codes),
    forall(member(Code, Codes),
           memberchk(Code, [0' , 0'\t, 0'\f, 0'\v])).


                 /*******************************
                 *            TOKENS            *
                 *******************************/

%   The stream is read in blocks (whatever is available, see
%   fill_buffer/1 and read_pending_codes/3) and each block is cut into
%   tokens: text(Bytes) for a non-empty run of bytes other than `\n` and
%   `\r` (Bytes is a string of characters 0..255, one per byte), `nl`
%   and `cr`.  `#end#` is found inside text tokens by the line reader.
%   All the per-byte work is done by C builtins.  (split_string/4
%   cannot cut data: in SWI-Prolog 9.0.4 it treats NUL as a separator
%   and as padding; so do read_string/5 and read_line_to_string/2.)

%!  next_token(+In, +Tokens0, -Token, -Tokens) is det.

next_token(_, [Token|Tokens], Token, Tokens) :-
    !.
next_token(In, [], Token, Tokens) :-
    read_block(In, Block),
    cut_block(Block, Tokens0),
    (   Tokens0 = [Token|Tokens]
    ->  true
    ;   Token = eof,
        Tokens = []
    ).

%!  read_block(+Source, -Block) is det.
%
%   Read the next block from Source, blocking until some bytes are
%   available: Block is a string of bytes (characters 0..255), "" at
%   end of file.  Source is source(In, Mode, MaxLines), see
%   byte_mode/3 and oro_reader/3.

read_block(source(In, Mode, _), Block) :-
    fill_buffer(In),
    read_pending_codes(In, Codes, []),
    (   Codes == []
    ->  Block = ""
    ;   block(Mode, Codes, Block)
    ).

%!  cut_block(+Block, -Tokens) is det.
%
%   The tokens of a block; [] for "".

cut_block(Block, Tokens) :-
    (   Block == ""
    ->  Tokens = []
    ;   plain_block(Block)                      % the usual case
    ->  split_string(Block, "\n", "", Lines),
        lines_tokens(Lines, Tokens)
    ;   general_block_tokens(Block, Tokens)
    ).

%   plain_block(+Block): Block has no `\r` and no NUL, so its lines are
%   what split_string/4 cuts at `\n`.

plain_block(Block) :-
    \+ sub_atom_icasechk(Block, _, "\r"),
    \+ sub_atom_icasechk(Block, _, "\u0000").

%   lines_tokens(+Lines, -Tokens): the tokens of a block without `\r`
%   split on `\n` into Lines: a `nl` between two lines, empty texts
%   left out.  (The block has no NUL either, which split_string/4 would
%   take for a separator.  sub_atom_icasechk/3 looks for one character
%   several times faster than split_string/4.)  The tests check that it
%   agrees with general_block_tokens/2.

lines_tokens([Line|Lines], Tokens) :-
    (   Line == ""
    ->  Tokens = Tokens1
    ;   Tokens = [text(Line)|Tokens1]
    ),
    (   Lines == []
    ->  Tokens1 = []
    ;   Tokens1 = [nl|Tokens2],
        lines_tokens(Lines, Tokens2)
    ).

%   general_block_tokens(+Block, -Tokens): the tokens of any block,
%   from the offsets of its `\n` and `\r`.

general_block_tokens(Block, Tokens) :-
    (   (   sub_atom_icasechk(Block, _, "\n")
        ;   sub_atom_icasechk(Block, _, "\r")
        )
    ->  findall(At-nl, sub_string(Block, At, 1, _, "\n"), Newlines),
        findall(At-cr, sub_string(Block, At, 1, _, "\r"), Returns),
        append(Newlines, Returns, Separators0),
        keysort(Separators0, Separators),
        block_tokens(Separators, Block, 0, Tokens)
    ;   Tokens = [text(Block)]
    ).

block(bytes, Codes, Block) :-
    string_codes(Block, Codes).
block(text, Codes, Block) :-
    string_codes(Text, Codes),
    recode(Text, utf8, Block, octet).

block_tokens([], Block, From, Tokens) :-
    string_length(Block, End),
    text_token(Block, From, End, Tokens, []).
block_tokens([At-Separator|Separators], Block, From, Tokens) :-
    text_token(Block, From, At, Tokens, [Separator|Tokens1]),
    Next is At + 1,
    block_tokens(Separators, Block, Next, Tokens1).

text_token(Block, From, To, Tokens, Tail) :-
    (   To > From
    ->  Len is To - From,
        sub_string(Block, From, Len, _, Text),
        Tokens = [text(Text)|Tail]
    ;   Tokens = Tail
    ).

%   skipped_token(+Skip, +In, +Tokens0, -Token, -Tokens)
%
%   Next token after skipping what Skip says may be skipped.

skipped_token(none, In, Tokens0, Token, Tokens) :-
    next_token(In, Tokens0, Token, Tokens).
skipped_token(lf, In, Tokens0, Token, Tokens) :-
    next_token(In, Tokens0, Token0, Tokens1),
    (   Token0 == nl
    ->  next_token(In, Tokens1, Token, Tokens)
    ;   Token = Token0,
        Tokens = Tokens1
    ).
skipped_token(eol, In, Tokens0, Token, Tokens) :-
    next_token(In, Tokens0, Token0, Tokens1),
    (   Token0 == nl
    ->  next_token(In, Tokens1, Token, Tokens)
    ;   Token0 == cr
    ->  skipped_token(lf, In, Tokens1, Token, Tokens)
    ;   Token = Token0,
        Tokens = Tokens1
    ).


                 /*******************************
                 *          LINE READER         *
                 *******************************/

%!  read_line(+In, +Max, +Skip0, +Tokens0,
%!            -Line, -Term, -Used, -Skip, -Tokens) is det.
%
%   Read one line of at most Max bytes.  Line is a string, or `invalid`
%   if the line is not valid UTF-8.  Term says how the line ended:
%   `nl` (`\n` or `\r`), `end` (`#end#`, not part of Line), `eof` or
%   `too_large` (more than Max bytes; reading stopped there).  Used is
%   the number of bytes the line consumed, Skip and Tokens the state
%   for what follows.

read_line(In, Max, Skip0, Tokens0, Line, Term, Used, Skip, Tokens) :-
    skipped_token(Skip0, In, Tokens0, Token, Tokens1),
    line(Token, In, Max, raw([], 0, ""), 0, [], true, Tokens1,
         Line, Term, Used, Skip, Tokens).

%!  skip_line(+In, +Max, +Skip0, +Tokens0,
%!            -Term, -Used, -Skip, -Tokens) is det.
%
%   As read_line/9, but the content of the line is not kept.

skip_line(In, Max, Skip0, Tokens0, Term, Used, Skip, Tokens) :-
    skipped_token(Skip0, In, Tokens0, Token, Tokens1),
    line(Token, In, Max, raw([], 0, ""), 0, [], false, Tokens1,
         _, Term, Used, Skip, Tokens).

%   line(+Token, +In, +Max, +Raw, +Used0, +Chunks, +Valid, +Tokens0,
%        -Line, -Term, -Used, -Skip, -Tokens)
%
%   Raw is raw(Parts, Len, Tail): the bytes of the line not decoded yet
%   as a reversed list of strings, their number, and their last (up to)
%   4 bytes, where a `#end#` split over two blocks may start.  Chunks
%   holds the decoded earlier parts of a long line (reversed).  Valid
%   is `false` once the line is known to be invalid UTF-8 (or its
%   content is not wanted); then only Tail is kept.

line(Token, In, Max, Raw, Used0, Chunks, Valid, Tokens0,
     Line, Term, Used, Skip, Tokens) :-
    (   Raw = raw([], 0, ""),
        Chunks == [],
        Valid == true,
        line_fast(Token, Max, Used0, Tokens0, Line1, Term1, Used1, Skip1,
                  Tokens1)
    ->  Line = Line1,
        Term = Term1,
        Used = Used1,
        Skip = Skip1,
        Tokens = Tokens1
    ;   line_(Token, In, Max, Raw, Used0, Chunks, Valid, Tokens0,
              Line, Term, Used, Skip, Tokens)
    ).

%   line_fast(+Token, +Max, +Used0, +Tokens0,
%             -Line, -Term, -Used, -Skip, -Tokens) is semidet.
%
%   The usual cases, at the start of a line, decided from Token and the
%   tokens already read (it never reads): a bare `#end#` and a short
%   whole line (text followed by its line end) without `#end#`.  It
%   gives what line_/13 gives and fails for everything else (a text
%   with `#end#` in any case, a line end not read yet, too large or
%   invalid UTF-8).

line_fast(text(Part), Max, Used0, Tokens0, Line, Term, Used, Skip, Tokens) :-
    (   Part == "#end#"
    ->  Used is Used0 + 5,
        Used =< Max,
        Line = "",
        Term = end,
        Skip = eol,
        Tokens = Tokens0
    ;   Tokens0 = [End|Tokens],
        line_end_skip(End, Skip),
        \+ sub_atom_icasechk(Part, _, "#end#"),
        string_length(Part, Len),
        Used0 + Len =< Max,
        utf8_decode(Part, Line),
        Term = nl,
        Used is Used0 + Len + 1
    ).

line_end_skip(nl, none).
line_end_skip(cr, lf).

line_(eof, _, _, _, Used, _, _, _, "", eof, Used, none, []).
line_(nl, _, _, Raw, Used0, Chunks, Valid, Tokens, Line, nl, Used, none, Tokens) :-
    Used is Used0 + 1,
    raw_string(Raw, Bytes),
    line_text(Valid, Bytes, Chunks, Line).
line_(cr, _, _, Raw, Used0, Chunks, Valid, Tokens, Line, nl, Used, lf, Tokens) :-
    Used is Used0 + 1,
    raw_string(Raw, Bytes),
    line_text(Valid, Bytes, Chunks, Line).
line_(text(Part), In, Max, raw(Parts0, Len0, Tail0), Used0, Chunks0, Valid0,
      Tokens0, Line, Term, Used, Skip, Tokens) :-
    string_length(Part, PartLen),
    string_concat(Tail0, Part, Window),
    (   end_marker(Window, Offset)
    ->  RestAt is Offset + 5,
        sub_string(Window, RestAt, RestLen, 0, Rest),
        Used1 is Used0 + PartLen - RestLen,
        (   Used1 > Max
        ->  too_large(Used1, Line, Term, Used, Skip, Tokens)
        ;   Term = end,
            Used = Used1,
            Skip = eol,
            (   RestLen =:= 0
            ->  Tokens = Tokens0
            ;   Tokens = [text(Rest)|Tokens0]
            ),
            (   Valid0 == true
            ->  string_length(Tail0, TailLen),
                ContentLen is Len0 - TailLen + Offset,
                raw_string(raw([Part|Parts0], _, _), Bytes0),
                sub_string(Bytes0, 0, ContentLen, _, Bytes),
                line_text(true, Bytes, Chunks0, Line)
            ;   Line = invalid
            )
        )
    ;   Used1 is Used0 + PartLen,
        (   Used1 > Max
        ->  too_large(Used1, Line, Term, Used, Skip, Tokens)
        ;   last_bytes(Window, Tail),
            Len1 is Len0 + PartLen,
            cut_chunk(Valid0, raw([Part|Parts0], Len1, Tail), Chunks0,
                      Raw, Chunks, Valid),
            next_token(In, Tokens0, Token, Tokens1),
            line(Token, In, Max, Raw, Used1, Chunks, Valid, Tokens1,
                 Line, Term, Used, Skip, Tokens)
        )
    ).

too_large(Used, "", too_large, Used, none, []).

%   end_marker(+Window, -Offset) is semidet.
%
%   The first `#end#` in Window starts at Offset.  sub_atom_icasechk/3
%   is the fastest search SWI-Prolog has; a case-insensitive hit such
%   as `#END#` is checked and skipped.

end_marker(Window, Offset) :-
    sub_atom_icasechk(Window, Offset0, "#end#"),
    (   sub_string(Window, Offset0, 5, _, "#end#")
    ->  Offset = Offset0
    ;   Skip is Offset0 + 1,
        sub_string(Window, Skip, _, 0, Rest),
        end_marker(Rest, Offset1),
        Offset is Skip + Offset1
    ).

raw_string(raw([], _, _), "") :-
    !.
raw_string(raw([Bytes], _, _), Bytes) :-
    !.
raw_string(raw(Parts, _, _), Bytes) :-
    reverse(Parts, Parts1),
    atomics_to_string(Parts1, Bytes).

%   cut_chunk(+Valid0, +Raw0, +Chunks0, -Raw, -Chunks, -Valid)
%
%   Keep Raw small: once it reaches the chunk size decode all but its
%   last 4 bytes (a possible partial `#end#`), cutting at a character
%   boundary.  A chunk that is not valid UTF-8 makes the line invalid.

cut_chunk(false, raw(_, _, Tail), _, raw([], 0, Tail), [], false) :-
    !.
cut_chunk(true, Raw0, Chunks0, Raw, Chunks, Valid) :-
    Raw0 = raw(_, Len, Tail),
    chunk_size(Size),
    (   Len < Size
    ->  Raw = Raw0,
        Chunks = Chunks0,
        Valid = true
    ;   raw_string(Raw0, Bytes),
        Cut0 is Len - 4,
        char_boundary(Bytes, Cut0, 3, Cut),
        sub_string(Bytes, 0, Cut, RestLen, Chunk),
        sub_string(Bytes, Cut, RestLen, 0, Rest),
        (   utf8_decode(Chunk, Text)
        ->  Raw = raw([Rest], RestLen, Tail),
            Chunks = [Text|Chunks0],
            Valid = true
        ;   Raw = raw([], 0, Tail),
            Chunks = [],
            Valid = false
        )
    ).

last_bytes(String, Last) :-
    string_length(String, Len),
    (   Len =< 4
    ->  Last = String
    ;   sub_string(String, _, 4, 0, Last)
    ).

%   char_boundary(+Raw, +Cut0, +Tries, -Cut)
%
%   Cut =< Cut0 is the offset of a byte that starts a character (ASCII
%   or a UTF-8 lead byte).  If the 4 bytes before Cut0 are all
%   continuation bytes the text is invalid anyway and Cut0 is used.

char_boundary(Raw, Cut0, Tries, Cut) :-
    sub_string(Raw, Cut0, 1, _, Char),      % string_code/3 copies Raw
    string_code(1, Char, Byte),
    (   (   Byte < 0x80
        ;   Byte >= 0xC0
        )
    ->  Cut = Cut0
    ;   Tries =:= 0
    ->  Cut = Cut0
    ;   Cut1 is Cut0 - 1,
        Tries1 is Tries - 1,
        char_boundary(Raw, Cut1, Tries1, Cut)
    ).

%   line_text(+Valid, +Raw, +Chunks, -Line)

line_text(false, _, _, invalid) :-
    !.
line_text(true, Raw, Chunks, Line) :-
    (   utf8_decode(Raw, Last)
    ->  (   Chunks == []
        ->  Line = Last
        ;   reverse([Last|Chunks], Parts),
            atomics_to_string(Parts, Line)
        )
    ;   Line = invalid
    ).


                 /*******************************
                 *             UTF-8            *
                 *******************************/

%!  utf8_decode(+Bytes, -Text) is semidet.
%
%   Decode Bytes, a string of characters 0..255, as strict UTF-8 (RFC
%   3629); fail if it is not valid.
%
%   SWI-Prolog's decoder is lenient (an illegal byte becomes the
%   Latin-1 character, overlong forms are accepted), but it encodes
%   canonically, so re-encoding the text and comparing with the input
%   rejects illegal, truncated and overlong sequences.  What that
%   round trip lets through (surrogates, code points above U+10FFFF)
%   needs a lead byte 0xED or 0xF4..0xFF: only text with one of those
%   is checked byte by byte.  ASCII text is returned as is.
%   (split_string/4 also reports NUL as a separator; that only sends
%   text with NUL down a slower path.)

utf8_decode(Bytes, Text) :-
    high_bytes(High),
    (   split_string(Bytes, High, "", [_])
    ->  Text = Bytes                    % ASCII
    ;   suspect_leads(Suspects),
        (   split_string(Bytes, Suspects, "", [_])
        ->  true
        ;   string_codes(Bytes, Codes),
            utf8_valid(Codes)
        ),
        recode(Bytes, octet, Text, utf8),
        recode(Text, utf8, Bytes1, octet),
        Bytes1 == Bytes
    ).

%   recode(+Text0, +Encoding0, -Text, +Encoding)
%
%   Write Text0 to a memory file in Encoding0 and read it back in
%   Encoding (no lists, so no pressure on the stacks).

recode(Text0, Encoding0, Text, Encoding) :-
    setup_call_cleanup(
        new_memory_file(MemFile),
        ( setup_call_cleanup(
              open_memory_file(MemFile, write, Out, [encoding(Encoding0)]),
              write(Out, Text0),
              close(Out)),
          memory_file_to_string(MemFile, Text, Encoding)
        ),
        free_memory_file(MemFile)).

%   high_bytes(-Set): the bytes 0x80..0xFF, as a string.
%   suspect_leads(-Set): the lead bytes the round trip cannot judge.
%   (Both computed at compile time.)

term_expansion(high_bytes(generated), high_bytes(Set)) :-
    numlist(0x80, 0xFF, Codes),
    string_codes(Set, Codes).
term_expansion(suspect_leads(generated), suspect_leads(Set)) :-
    numlist(0xF4, 0xFF, High),
    string_codes(Set, [0xED|High]).

high_bytes(generated).
suspect_leads(generated).

%   utf8_valid(+Bytes) is semidet.

utf8_valid([]).
utf8_valid([B|Bs]) :-
    (   B < 0x80
    ->  utf8_valid(Bs)
    ;   utf8_lead(B, Length, Low, High),
        Bs = [C|Bs1],
        C >= Low,
        C =< High,
        Count is Length - 2,
        utf8_continuations(Count, Bs1, Bs2),
        utf8_valid(Bs2)
    ).

utf8_continuations(0, Bs, Bs) :-
    !.
utf8_continuations(Count, [C|Bs0], Bs) :-
    C >= 0x80,
    C =< 0xBF,
    Count1 is Count - 1,
    utf8_continuations(Count1, Bs0, Bs).

%   utf8_lead(+Byte, -Length, -Low, -High) is semidet.
%
%   Byte starts a character of Length bytes whose second byte is in
%   Low..High (RFC 3629 table 3-7: no overlong forms, no surrogates,
%   nothing above U+10FFFF).

utf8_lead(B, Length, Low, High) :-
    (   B < 0xC2
    ->  fail
    ;   B =< 0xDF
    ->  Length = 2, Low = 0x80, High = 0xBF
    ;   B =:= 0xE0
    ->  Length = 3, Low = 0xA0, High = 0xBF
    ;   B =:= 0xED
    ->  Length = 3, Low = 0x80, High = 0x9F
    ;   B =< 0xEF
    ->  Length = 3, Low = 0x80, High = 0xBF
    ;   B =:= 0xF0
    ->  Length = 4, Low = 0x90, High = 0xBF
    ;   B =< 0xF3
    ->  Length = 4, Low = 0x80, High = 0xBF
    ;   B =:= 0xF4
    ->  Length = 4, Low = 0x80, High = 0x8F
    ).


                 /*******************************
                 *            WRITING           *
                 *******************************/

%!  oro_write_ok(+Out, +Value) is det.
%
%   Write a success response `ok\n<value>\n#end#\n` and flush.  Value
%   is a value term of oro_encode_value/2.  The message is written with
%   one write and one flush; the caller holds the connection's mutex.

oro_write_ok(Out, Value) :-
    must_be(stream, Out),
    oro_encode_value(Value, Text),
    atomics_to_string(["ok\n", Text, "\n#end#\n"], Message),
    write_message(Out, Message).

%!  oro_write_error(+Out, +ExceptionName, +Message) is det.
%
%   Write an error response `error\n<name>\n<message>\n#end#\n` and
%   flush.  ExceptionName and Message are text (atoms, strings, numbers
%   or code lists); newlines in them (`\n`, `\r\n`, `\r`) become spaces
%   so each stays on one line (recommended deviation of ORO-SPEC §1.3).

oro_write_error(Out, Name, Message) :-
    must_be(stream, Out),
    one_line_text(Name, NameLine),
    one_line_text(Message, MessageLine),
    atomics_to_string(["error\n", NameLine, "\n", MessageLine, "\n#end#\n"],
                      Text),
    write_message(Out, Text).

%!  oro_write_event(+Out, +WatcherId, +Content) is det.
%
%   Write an event `event\n<id>\n<content>\n#end#\n` and flush.
%   WatcherId is text, written unquoted; Content is a value term
%   (`void` for the empty line of FACT_CHECKING events, list/1 of ids
%   for the others).

oro_write_event(Out, Id, Content) :-
    must_be(stream, Out),
    one_line_text(Id, IdLine),
    oro_encode_value(Content, Text),
    atomics_to_string(["event\n", IdLine, "\n", Text, "\n#end#\n"], Message),
    write_message(Out, Message).

%!  oro_write_closing(+Out) is det.
%
%   Write `Closing now!\n` (the answer to `close`: no `ok`, no `#end#`)
%   and flush.

oro_write_closing(Out) :-
    must_be(stream, Out),
    write_message(Out, "Closing now!\n").

write_message(Out, Message) :-
    write(Out, Message),
    flush_output(Out).

one_line_text(Text, Line) :-
    must_be_text(Text, String),
    replace_all(String, ["\r\n"-" ", "\r"-" ", "\n"-" "], Line).

must_be_text(Text, String) :-
    (   var(Text)
    ->  instantiation_error(Text)
    ;   atomic(Text)
    ->  atom_string(Text, String)
    ;   is_list(Text),
        catch(string_codes(String, Text), _, fail)
    ->  true
    ;   catch(string_chars(String, Text), _, fail)
    ->  true
    ;   type_error(text, Text)
    ).


                 /*******************************
                 *            VALUES            *
                 *******************************/

%!  oro_encode_value(+Value, -String) is det.
%
%   Encode a return value as the text of the value line (ORO-SPEC §3).
%   Value is one of:
%
%     - void                  the empty string (void methods)
%     - bool(true|false)      `true` / `false`
%     - string(Text)          a quoted string, see "Plain strings" below
%     - multiline_string(Text) `"Text"` with `\` and `"` escaped and
%                             newlines kept raw (only for `help`)
%     - raw(Text)             Text as is (UUIDs, JSON), but a line
%                             break (`\r\n`, `\r`, `\n`) is a space
%     - null                  `null`
%     - int(N), float(X)      the number (`Infinity`, `NaN` as Java)
%     - list(Values)          `[v1,v2]`, no spaces
%     - map(Pairs)            `{k1:v1,k2:v2}`, no spaces; Pairs are
%                             Key-Value
%
%   Elements of lists and maps (keys included) are value terms, plain
%   strings and atoms (encoded as strings; `true` and `false` too, use
%   bool/1 for booleans), plain numbers, or the atom `null`.  `void` and
%   multiline_string/1 are not elements.
%
%   The escaping is chosen so that the two real clients read every
%   value back: liboro, which strips one pair of quotes from a value
%   line and cuts lists and maps with Boost's `escaped_list_separator`
%   (escapes `\\`, `\"`, `\,` and `\n` only: any other escape throws
%   and aborts the client), and pyoro, which eval()s the line as a
%   Python literal.  No value line contains a raw line break (`\n` or
%   `\r`), so none can read as `#end#`.
%
%     - **Strings inside lists and maps** are quoted with `"`; `\` and
%       `"` are written `\\` and `\"`, a line break (`\n`, `\r\n` or a
%       lone `\r`) is written `\n`, NUL becomes U+FFFD, every other
%       character (TAB, other control characters, commas, brackets,
%       non-BMP characters) is written raw.  Both clients read these
%       escapes alike and read raw characters as themselves.  CR and
%       NUL have no representation both can read: `\r` or `\u0000`
%       would abort liboro, a raw CR is a line break for pyoro (its
%       socket file reads with universal newlines) and a raw NUL ends
%       liboro's C string; so a CR reads back as a newline, as the
%       request reader reads it, and a NUL as U+FFFD.
%     - **Plain strings** (a string(Text) reply: `getLabel`, `hello`)
%       are not cut by liboro, which shows what lies between the quotes
%       as is, like oro-server 0.8.2 wrote it.  So Text is written
%       verbatim between `"` (or between `'` if it has a `"` but no
%       `'`; both clients strip either quote and Python reads both),
%       unless it contains a line break or NUL (that would break the
%       framing) or both quote characters (that could close pyoro's
%       literal early and have it eval the rest of the label as
%       code).  Then it is written `"` + Text + `"` with `\\`, `\"`,
%       `\n`, `\r` and `\u0000`: pyoro reads it exactly, liboro shows
%       the escapes.  A backslash in a verbatim string is read as an
%       escape by pyoro, as it was from oro-server 0.8.2.
%
%   @error type_error(oro_value, Value) for anything else.

oro_encode_value(Value, String) :-
    must_be(nonvar, Value),
    value(Value, Parts, []),
    !,
    atomics_to_string(Parts, String).
oro_encode_value(Value, _) :-
    type_error(oro_value, Value).

value(string(Text), [Quote, Escaped, Quote|T], T) :-
    !,
    text_string(Text, String),
    reply_string(String, Quote, Escaped).
value(multiline_string(Text), ["\"", Escaped, "\""|T], T) :-
    !,
    text_string(Text, String),
    replace_all(String, [ "\\"-"\\\\", "\""-"\\\"" ], Escaped).
value(list(Values), ["[\"", Joined, "\"]"|T], T) :-
    Values = [_|_],
    plain_elements(Values, Texts),          % the usual case: strings
    atomic_list_concat(Texts, ",", All),
    plain_element(All),                     % one scan for the list
    !,
    atomic_list_concat(Texts, "\",\"", Joined).
value(list(Values), ["["|T0], T) :-
    !,
    is_list(Values),
    elements(Values, T0, ["]"|T]).
value(map(Pairs), ["{"|T0], T) :-
    !,
    is_list(Pairs),
    pairs(Pairs, T0, ["}"|T]).
value(Value, T0, T) :-
    scalar(Value, T0, T).

scalar(void, T, T).
scalar(null, ["null"|T], T).
scalar(bool(B), [B|T], T) :-
    (   B == true
    ;   B == false
    ),
    !.
scalar(raw(Text), [Line|T], T) :-
    text_string(Text, String),
    (   split_string(String, "\n\r", "", [_])
    ->  Line = String
    ;   replace_all(String, ["\r\n"-" ", "\r"-" ", "\n"-" "], Line)
    ).
scalar(int(N), [N|T], T) :-
    integer(N).
scalar(float(X), [Text|T], T) :-
    number(X),
    float_text(X, Text).

elements([], T, T).
elements([H|R], T0, T) :-
    element(H, T0, T1),
    elements_rest(R, T1, T).

elements_rest([], T, T).
elements_rest([H|R], [","|T0], T) :-
    element(H, T0, T1),
    elements_rest(R, T1, T).

pairs([], T, T).
pairs([P|R], T0, T) :-
    pair(P, T0, T1),
    pairs_rest(R, T1, T).

pairs_rest([], T, T).
pairs_rest([P|R], [","|T0], T) :-
    pair(P, T0, T1),
    pairs_rest(R, T1, T).

pair(Key-Value, T0, T) :-
    element(Key, T0, [":"|T1]),
    element(Value, T1, T).

element(E, T0, T) :-
    (   var(E)
    ->  fail
    ;   string(E)
    ->  element_string(E, T0, T)
    ;   integer(E)
    ->  scalar(int(E), T0, T)
    ;   float(E)
    ->  scalar(float(E), T0, T)
    ;   E == null
    ->  scalar(null, T0, T)
    ;   atom(E)
    ->  element_string(E, T0, T)
    ;   E = string(Text)
    ->  element_string(Text, T0, T)
    ;   E \= void,
        E \= multiline_string(_),
        value(E, T0, T)
    ).

%!  oro_encode_string(+Text, -Quoted) is det.
%
%   Quoted is Text as a string inside a list or a map of a value line
%   (see oro_encode_value/2), for replies that build their text
%   themselves, such as the JSON of `getResourceDetails`: liboro
%   tokenises every reply that looks like a map, so a JSON escape such
%   as `\t` there would abort it.
%
%   @error type_error(text, Text) if Text is not text.

oro_encode_string(Text, Quoted) :-
    must_be_text(Text, String),
    element_string(String, Parts, []),
    atomics_to_string(Parts, Quoted).

element_string(Text, ["\"", Escaped, "\""|T], T) :-
    text_string(Text, String),
    (   plain_element(String)
    ->  Escaped = String
    ;   element_escapes(Escapes),
        replace_all(String, Escapes, Escaped)
    ).

%   plain_elements(+Values, -Texts) is semidet.
%
%   Values are list elements that are all encoded as strings (string(T)
%   with T an atom or a string, a string, an atom but `null`); Texts are
%   their texts.  If none of them needs escaping (plain_element/1 on
%   all of them at once), the list is `["` + their join by `","` + `"]`.

plain_elements([], []).
plain_elements([Value|Values], [Text|Texts]) :-
    (   string(Value)
    ->  Text = Value
    ;   atom(Value)
    ->  Value \== null,
        Text = Value
    ;   Value = string(Text),
        (   atom(Text)
        ->  true
        ;   string(Text)
        )
    ),
    plain_elements(Values, Texts).

text_string(Text, String) :-
    (   string(Text)
    ->  String = Text
    ;   atomic(Text)
    ->  atom_string(Text, String)
    ;   is_list(Text)
    ->  catch(text_to_string(Text, String), _, fail)
    ).

float_text(X, Text) :-
    (   float(X)
    ->  Y = X
    ;   Y is float(X)
    ),
    float_class(Y, Class),
    (   Class == nan
    ->  Text = "NaN"
    ;   Class == infinite
    ->  (   Y > 0
        ->  Text = "Infinity"
        ;   Text = "-Infinity"
        )
    ;   format(string(Text), "~w", [Y])
    ).

%   element_escapes(-Replacements)
%
%   The escapes of a string inside a list or a map: only those Boost's
%   escaped_list_separator and Python read alike (`\\`, `\"`, `\n`);
%   CR and NUL have none (see oro_encode_value/2).

element_escapes([ "\\"-"\\\\", "\""-"\\\"",
                  "\r\n"-"\\n", "\r"-"\\n", "\n"-"\\n",
                  "\u0000"-"\uFFFD"
                ]).

%   plain_element(+String): String is written as is inside a list or a
%   map (no `\`, `"`, line break or NUL).  One C-level scan.

plain_element(String) :-
    split_string(String, "\\\"\n\r", "", [_]),
    \+ sub_string(String, _, _, _, "\u0000").

%   reply_string(+String, -Quote, -Text)
%
%   A plain string reply is Quote + Text + Quote: String verbatim when
%   that is safe, else escaped for Python (see oro_encode_value/2).

reply_string(String, Quote, Text) :-
    split_string(String, "\n\r\"", "", [_]),   % the usual case: one scan
    \+ sub_string(String, _, _, _, "\u0000"),
    !,
    Quote = "\"",
    Text = String.
reply_string(String, Quote, Text) :-
    (   split_string(String, "\n\r", "", [_]),
        \+ sub_string(String, _, _, _, "\u0000"),
        verbatim_quote(String, Quote0)
    ->  Quote = Quote0,
        Text = String
    ;   Quote = "\"",
        replace_all(String,
                    [ "\\"-"\\\\", "\""-"\\\"", "\n"-"\\n", "\r"-"\\r",
                      "\u0000"-"\\u0000"
                    ],
                    Text)
    ).

verbatim_quote(String, Quote) :-
    (   sub_string(String, _, _, _, "\"")
    ->  \+ sub_string(String, _, _, _, "'"),
        Quote = "'"
    ;   Quote = "\""
    ).

%!  replace_all(+String, +Replacements, -Result) is det.
%
%   Replace every occurrence of each From in the From-To pairs of
%   Replacements (From has no letters: the pre-check is
%   case-insensitive), scanning String with C builtins only (so
%   multi-megabyte strings stay cheap and NUL characters are safe).
%   Where matches overlap the leftmost wins, then the longest.

replace_all(String, Replacements, Result) :-
    findall(hit(At, Minus, To),
            ( member(From-To, Replacements),
              sub_atom_icasechk(String, _, From),   % fast pre-check
              string_length(From, Len),
              Minus is -Len,
              sub_string(String, At, Len, _, From)
            ),
            Hits0),
    (   Hits0 == []
    ->  Result = String
    ;   msort(Hits0, Hits),
        replaced_parts(Hits, String, 0, Parts),
        atomics_to_string(Parts, Result)
    ).

replaced_parts([], String, From, [Rest]) :-
    sub_string(String, From, _, 0, Rest).
replaced_parts([hit(At, Minus, To)|Hits], String, From, Parts) :-
    (   At < From
    ->  replaced_parts(Hits, String, From, Parts)
    ;   Len is At - From,
        sub_string(String, From, Len, _, Before),
        Parts = [Before, To|Parts1],
        Next is At - Minus,
        replaced_parts(Hits, String, Next, Parts1)
    ).
