:- module(oro_client_parsers,
          [ liboro_read_line/2,         % +Line, -Result
            liboro_tokens/2,            % +Text, -Tokens
            liboro_clean/2,             % +Text, -Clean
            pyoro_read_line/2,          % +Line, -Result
            python_literal/2,           % +Text, -Result
            liboro_view/2,              % +PythonValue, -LiboroValue
            reply_line_problem/3        % +Kind, +Line, -Problem
          ]).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(pairs)).

/** <module> How liboro and pyoro read a value line

A re-implementation, for tests, of the rules by which the two real ORO
clients decode the value line of a reply or the content line of an
event.  The server cannot run the clients in CI, so the tests check
every reply against these emulations.

**liboro 1.3.1** (C++, `SocketConnector::read`, `deserialize`,
`makeCollec`, `cleanValue`):

  - A line is read into a C string: a NUL byte ends it (and makes
    liboro's line search fail).
  - cleanValue: spaces and TABs are trimmed at both ends, then one pair
    of enclosing `"` or `'` is removed.
  - deserialize: `true`, `false`; a text that starts with `[` and ends
    with `]` (or `{` and `}`) is a collection; else an int, a double,
    else the text.
  - makeCollec: the brackets are removed and the rest is cut by Boost's
    `escaped_list_separator<char>` (escape `\`, separator `,`, quote
    `"`): an unquoted `,` ends a token, `"` toggles quoting and is
    dropped, `\n` is a newline, `\"`, `\,` and `\\` are the character;
    any other escape, or an escape at the end, throws
    `escaped_list_error`, which liboro does not catch: the client
    aborts.  If the rest starts with `[` and ends with `]` it is a list
    of pairs (`[["a","b"],...]`), read as a map; a `{...}` is a map
    whose tokens are cut at their first `:`; else a set.  Every token
    goes through cleanValue.

**pyoro** (threaded, `get_oro_response`): the socket is read through
a text file, so `\r`, `\r\n` and `\n` all end a line; a line `true` or
`false` (any case) is a boolean; an empty line is skipped; any other
line is `eval()`ed, and a SyntaxError or NameError leaves the line as a
string.  python_literal/2 implements the part of Python 3 expression
syntax and evaluation that such lines can hold: string literals with
Python's escapes (and implicit concatenation), int and float literals,
`True`, `False`, `None`, lists, dicts, sets and tuples, unary and binary `+` and
`-`, comments; names are NameErrors, source with NUL a SyntaxError
(ValueError before Python 3.11.4).  What lies outside this subset is
reported as unsupported(What), never guessed.

Results:

  - liboro: value(V) with V one of bool(B), int(N), double(Text),
    string(S), set(SortedStrings), map(SortedPairs); error(Why) for an
    OntologyServerException liboro reports to its caller; crash(Why)
    for what aborts the client or corrupts its stream.
  - pyoro: value(V) with V one of str(S), num(Text, N), bool(B), none,
    list(Vs), dict(Pairs), set(Vs), tuple(Vs); raw(Line) when eval() failed with a
    SyntaxError or NameError; skipped for an empty line; crash(Why) for
    an exception pyoro does not catch; unsupported(What).
*/

                 /*******************************
                 *            LIBORO            *
                 *******************************/

%!  liboro_read_line(+Line, -Result) is det.
%
%   Result is what liboro makes of the value line Line (a string
%   without its `\n`).

liboro_read_line(Line, Result) :-
    (   sub_string(Line, _, _, _, "\u0000")
    ->  Result = crash(nul_in_line)
    ;   catch(( liboro_clean(Line, Clean),
                deserialize(Clean, Value),
                Result = value(Value)
              ),
              liboro(Outcome),
              Result = Outcome)
    ).

deserialize("true", bool(true)) :- !.
deserialize("false", bool(false)) :- !.
deserialize(Text, Value) :-
    string_codes(Text, Codes),
    (   Codes = [Open|_],
        last(Codes, Close),
        collection_brackets(Open, Close)
    ->  make_collection(Codes, Value)
    ;   cpp_int(Codes, N)
    ->  Value = int(N)
    ;   cpp_double(Codes)
    ->  Value = double(Text)
    ;   Value = string(Text)
    ).

collection_brackets(0'[, 0']).
collection_brackets(0'{, 0'}).

%   lexical_cast<int>: an optional sign and digits, in 32 bits.

cpp_int(Codes, N) :-
    sign_digits(Codes, Digits),
    Digits \== [],
    maplist(digit, Digits),
    number_codes(N0, Digits),
    (   Codes = [0'-|_]
    ->  N is -N0
    ;   N = N0
    ),
    N >= -2147483648,
    N =< 2147483647.

sign_digits([0'-|Ds], Ds) :- !.
sign_digits([0'+|Ds], Ds) :- !.
sign_digits(Ds, Ds).

digit(C) :-
    between(0'0, 0'9, C).

%   lexical_cast<double>: a decimal number with optional exponent, or
%   inf, infinity, nan (any case), with an optional sign.

cpp_double(Codes) :-
    sign_digits(Codes, Rest),
    (   string_codes(S, Rest),
        string_lower(S, L),
        memberchk(L, ["inf", "infinity", "nan"])
    ->  true
    ;   mantissa(Rest, AfterMantissa),
        exponent(AfterMantissa)
    ).

mantissa(Codes, Rest) :-
    digits(Codes, Int, R0),
    (   R0 = [0'.|R1]
    ->  digits(R1, Frac, Rest),
        (   Int \== []
        ;   Frac \== []
        )
    ->  true
    ;   Int \== [],
        Rest = R0
    ).

exponent([]).
exponent([E|Codes]) :-
    memberchk(E, `eE`),
    sign_digits(Codes, Digits),
    Digits \== [],
    maplist(digit, Digits).

digits([C|Cs], [C|Ds], Rest) :-
    digit(C),
    !,
    digits(Cs, Ds, Rest).
digits(Rest, [], Rest).

make_collection(Codes, Value) :-
    once(append([Open|Inner], [_], Codes)),
    (   Inner = [0'[|_],
        last(Inner, 0'])
    ->  liboro_tokens_codes(Inner, Tokens),
        pair_map(Tokens, key, "", [], Pairs),
        Value = map(Pairs)
    ;   Open == 0'{
    ->  liboro_tokens_codes(Inner, Tokens),
        foldl(map_token, Tokens, [], Pairs),
        Value = map(Pairs)
    ;   liboro_tokens_codes(Inner, Tokens),
        maplist(liboro_clean, Tokens, Cleaned),
        sort(Cleaned, Set),
        Value = set(Set)
    ).

%   pair_map(+Tokens, +Expect, +LastKey, +Pairs0, -Pairs)
%
%   A list of pairs: a key token must start with `[`, a value token
%   end with `]` (else OntologyServerException); a key without value
%   maps to "".

pair_map([], _, _, Pairs, Pairs).
pair_map([Token|Tokens], Expect, Key0, Pairs0, Pairs) :-
    liboro_clean(Token, C),
    pair_token(Expect, C, Key0, Key, Next, Pairs0, Pairs1),
    pair_map(Tokens, Next, Key, Pairs1, Pairs).

pair_token(key, C, _, Key, value, Pairs0, Pairs) :-
    (   sub_string(C, 0, 1, After, "[")
    ->  sub_string(C, 1, After, 0, C1),
        liboro_clean(C1, Key),
        map_put(Key, "", Pairs0, Pairs)
    ;   throw(liboro(error(invalid_collection)))
    ).
pair_token(value, C, Key, "", key, Pairs0, Pairs) :-
    (   sub_string(C, Before, 1, 0, "]")
    ->  sub_string(C, 0, Before, _, C1),
        liboro_clean(C1, Value),
        map_put(Key, Value, Pairs0, Pairs)
    ;   throw(liboro(error(invalid_collection)))
    ).

map_token(Token, Pairs0, Pairs) :-
    (   sub_string(Token, Before, 1, _, ":")
    ->  !,
        sub_string(Token, 0, Before, _, K),
        Start is Before + 1,
        sub_string(Token, Start, _, 0, V),
        liboro_clean(K, Key),
        liboro_clean(V, Value),
        map_put(Key, Value, Pairs0, Pairs)
    ;   throw(liboro(error(missing_colon)))
    ).

%   map_put(+Key, +Value, +Pairs0, -Pairs): std::map assignment; Pairs
%   stay sorted by key.

map_put(Key, Value, Pairs0, Pairs) :-
    (   selectchk(Key-_, Pairs0, Pairs1)
    ->  true
    ;   Pairs1 = Pairs0
    ),
    keysort([Key-Value|Pairs1], Pairs).

%!  liboro_tokens(+Text, -Tokens) is det.
%
%   The tokens Boost's `escaped_list_separator<char>` (default
%   escape, separator and quote) makes of Text.  Throws
%   liboro(crash(escaped_list_error(Why))) where Boost throws.

liboro_tokens(Text, Tokens) :-
    string_codes(Text, Codes),
    liboro_tokens_codes(Codes, Tokens).

liboro_tokens_codes([], []) :-
    !.
liboro_tokens_codes(Codes, [Token|Tokens]) :-
    boost_field(Codes, false, TokenCodes, Rest, End),
    string_codes(Token, TokenCodes),
    (   End == separator
    ->  (   Rest == []
        ->  Tokens = [""]
        ;   liboro_tokens_codes(Rest, Tokens)
        )
    ;   Tokens = []
    ).

boost_field([], _, [], [], end).
boost_field([C|Cs], Quoted, Token, Rest, End) :-
    (   C == 0'\\
    ->  boost_escape(Cs, Char, Cs1),
        Token = [Char|Token1],
        boost_field(Cs1, Quoted, Token1, Rest, End)
    ;   C == 0',,
        Quoted == false
    ->  Token = [],
        Rest = Cs,
        End = separator
    ;   C == 0'"
    ->  negate(Quoted, Quoted1),
        boost_field(Cs, Quoted1, Token, Rest, End)
    ;   Token = [C|Token1],
        boost_field(Cs, Quoted, Token1, Rest, End)
    ).

negate(false, true).
negate(true, false).

boost_escape([], _, _) :-
    throw(liboro(crash(escaped_list_error(cannot_end_with_escape)))).
boost_escape([C|Cs], Char, Cs) :-
    (   C == 0'n
    ->  Char = 0'\n
    ;   memberchk(C, `",\\`)
    ->  Char = C
    ;   char_code(Name, C),
        throw(liboro(crash(escaped_list_error(unknown_escape(Name)))))
    ).

%!  liboro_clean(+Text, -Clean) is det.
%
%   liboro's cleanValue: trim spaces and TABs, then remove one pair of
%   enclosing `"` or `'`.

liboro_clean(Text, Clean) :-
    split_string(Text, "", " \t", [Trimmed]),
    string_length(Trimmed, Len),
    (   Len > 0,
        sub_string(Trimmed, 0, 1, _, Q),
        memberchk(Q, ["\"", "'"]),
        sub_string(Trimmed, _, 1, 0, Q)
    ->  Inner is max(0, Len - 2),
        sub_string(Trimmed, 1, Inner, _, Clean)
    ;   Clean = Trimmed
    ).


                 /*******************************
                 *             PYORO            *
                 *******************************/

%!  pyoro_read_line(+Line, -Result) is det.
%
%   Result is what pyoro's get_oro_response makes of one line (already
%   split as its text file splits: no `\r`, no `\n`).

pyoro_read_line("", skipped) :-
    !.
pyoro_read_line(Line, Result) :-
    string_lower(Line, Lower),
    (   Lower == "true"
    ->  Result = value(bool(true))
    ;   Lower == "false"
    ->  Result = value(bool(false))
    ;   python_literal(Line, Result0),
        (   Result0 = error(_)
        ->  Result = raw(Line)
        ;   Result = Result0
        )
    ).

%!  python_literal(+Text, -Result) is det.
%
%   What Python 3's eval() makes of Text: value(V), error(syntax) or
%   error(name) (the two pyoro catches), crash(Why) for an exception
%   pyoro does not catch, unsupported(What) outside the emulated
%   subset.

python_literal(Text, Result) :-
    string_codes(Text, Codes),
    (   memberchk(0, Codes)
    ->  Result = crash(nul_in_source)   % SyntaxError since 3.11.4
    ;   catch(( py_tokens(Codes, Tokens),
                (   phrase(py_top(Tree), Tokens)
                ->  py_eval(Tree, Value),
                    Result = value(Value)
                ;   Result = error(syntax)
                )
              ),
              python(Outcome),
              Result = Outcome)
    ).

%   Tokens: str(S), num(Text, N), name(Atom), punct(C).

py_tokens(Codes, Tokens) :-
    py_skip_blanks(Codes, Codes1),
    (   Codes1 == []
    ->  Tokens = []
    ;   Codes1 = [0'#|_]
    ->  Tokens = []
    ;   py_token(Codes1, Token, Rest),
        Tokens = [Token|Tokens1],
        py_tokens(Rest, Tokens1)
    ).

py_skip_blanks([C|Cs], Rest) :-
    memberchk(C, [0' , 0'\t, 0'\f]),
    !,
    py_skip_blanks(Cs, Rest).
py_skip_blanks(Cs, Cs).

py_token([Q|Cs], str(S), Rest) :-
    memberchk(Q, `"'`),
    !,
    (   Cs = [Q, Q|_]
    ->  throw(python(unsupported(triple_quoted_string)))
    ;   py_string_body(Cs, Q, Body, Rest),
        string_codes(S, Body)
    ).
py_token([C|Cs], Token, Rest) :-
    (   digit(C)
    ;   C == 0'.,
        Cs = [D|_],
        digit(D)
    ),
    !,
    py_number([C|Cs], Token, Rest).
py_token([U, Q|Cs], Token, Rest) :-
    memberchk(U, `uU`),
    memberchk(Q, `"'`),
    !,
    py_token([Q|Cs], Token, Rest).
py_token([C|Cs], name(Name), Rest) :-
    py_name_start(C),
    !,
    py_name_chars(Cs, More, Rest),
    atom_codes(Name, [C|More]),
    (   Rest = [Q|_],
        memberchk(Q, `"'`),
        downcase_atom(Name, Lower),
        Lower \== u                          % u"..." is "..."
    ->  (   memberchk(Lower, [r, b, f, br, rb, fr, rf])
        ->  throw(python(unsupported(string_prefix(Name))))
        ;   throw(python(error(syntax)))
        )
    ;   true
    ).
py_token([C|Cs], punct(C), Cs) :-
    memberchk(C, `[]{},:+-`),
    !.
py_token([C|_], _, _) :-
    (   memberchk(C, `()[]{}:;.,@=+-*/%&|^~<>!`)
    ->  char_code(Char, C),
        throw(python(unsupported(operator(Char))))
    ;   throw(python(error(syntax)))        % `\`, `$`, `?`, an emoji ...
    ).

py_name_start(C) :-
    code_type(C, csymf).

py_name_chars([C|Cs], [C|More], Rest) :-
    code_type(C, csym),
    !,
    py_name_chars(Cs, More, Rest).
py_name_chars(Rest, [], Rest).

%   py_string_body(+Codes, +Quote, -Body, -Rest): up to the closing
%   Quote, escapes decoded; a missing Quote is a SyntaxError.

py_string_body([], _, _, _) :-
    throw(python(error(syntax))).
py_string_body([C|Cs], Q, Body, Rest) :-
    (   C == Q
    ->  Body = [],
        Rest = Cs
    ;   C == 0'\\
    ->  py_escape(Cs, Body, Body1, Cs1),
        py_string_body(Cs1, Q, Body1, Rest)
    ;   Body = [C|Body1],
        py_string_body(Cs, Q, Body1, Rest)
    ).

py_escape([], _, _, _) :-
    throw(python(error(syntax))).
py_escape([C|Cs], Body, Tail, Rest) :-
    (   py_simple_escape(C, Code)
    ->  Body = [Code|Tail],
        Rest = Cs
    ;   between(0'0, 0'7, C)
    ->  py_octal([C|Cs], 3, 0, Code, Rest),
        Body = [Code|Tail]
    ;   py_hex_escape(C, Count)
    ->  length(Hex, Count),
        (   append(Hex, Rest, Cs),
            maplist(hex_digit, Hex, Values)
        ->  foldl(hex_add, Values, 0, Code),
            (   Code =< 0x10FFFF
            ->  Body = [Code|Tail]
            ;   throw(python(error(syntax)))
            )
        ;   throw(python(error(syntax)))
        )
    ;   C == 0'N
    ->  throw(python(unsupported(named_escape)))
    ;   Body = [0'\\, C|Tail],              % unknown escape: kept
        Rest = Cs
    ).

py_simple_escape(0'\\, 0'\\).
py_simple_escape(0'', 0'').
py_simple_escape(0'", 0'").
py_simple_escape(0'a, 7).
py_simple_escape(0'b, 8).
py_simple_escape(0'f, 12).
py_simple_escape(0'n, 10).
py_simple_escape(0'r, 13).
py_simple_escape(0't, 9).
py_simple_escape(0'v, 11).

py_hex_escape(0'x, 2).
py_hex_escape(0'u, 4).
py_hex_escape(0'U, 8).

py_octal([C|Cs], N, Acc, Code, Rest) :-
    N > 0,
    between(0'0, 0'7, C),
    !,
    Acc1 is Acc*8 + C - 0'0,
    N1 is N - 1,
    py_octal(Cs, N1, Acc1, Code, Rest).
py_octal(Rest, _, Code, Code, Rest).

hex_digit(C, V) :-
    code_type(C, xdigit(V)).

hex_add(V, Acc0, Acc) :-
    Acc is Acc0*16 + V.

%   Numbers: decimal ints (no leading zeros but 0), 0x, 0o and 0b ints,
%   floats; a letter or digit right after a number is a SyntaxError;
%   `_` in numbers and imaginary numbers are outside the subset.

py_number([0'0, B|Cs], num(Text, N), Rest) :-
    base_prefix(B, Base),
    !,
    py_name_chars(Cs, Chars, Rest),
    (   Chars \== [],
        maplist(base_digit(Base), Chars, Values)
    ->  foldl(base_add(Base), Values, 0, N),
        string_codes(Text, [0'0, B|Chars])
    ;   throw(python(error(syntax)))
    ).
py_number(Codes, num(Text, N), Rest) :-
    digits(Codes, Int, R0),
    (   R0 = [0'.|R1]
    ->  digits(R1, Frac, R2),
        Point = true
    ;   Frac = [],
        R2 = R0,
        Point = false
    ),
    (   R2 = [E|R3],
        memberchk(E, `eE`)
    ->  (   R3 = [S|R4],
            memberchk(S, `+-`)
        ->  Sign = [S]
        ;   Sign = [],
            R4 = R3
        ),
        digits(R4, Exp, Rest),
        (   Exp == []
        ->  throw(python(error(syntax)))
        ;   true
        ),
        Exponent = true
    ;   Sign = [],
        Exp = [],
        Rest = R2,
        Exponent = false
    ),
    number_end(Rest),
    append(Source, Rest, Codes),
    !,
    string_codes(Text, Source),
    (   ( Point == true ; Exponent == true )
    ->  (   Int == [] -> IntPart = `0` ; IntPart = Int ),
        (   Frac == [] -> FracPart = `0` ; FracPart = Frac ),
        append([IntPart, `.`, FracPart, `e`, Sign, Exp], Normal0),
        (   Exp == []
        ->  append(Normal, `e`, Normal0)
        ;   Normal = Normal0
        ),
        catch(number_codes(N, Normal),
              error(syntax_error(float_overflow), _),
              N = inf)                      % Python's float('inf')
    ;   Int = [0'0, _|_],
        \+ maplist(==(0'0), Int)
    ->  throw(python(error(syntax)))    % leading zeros
    ;   number_codes(N, Int)
    ).

number_end([C|_]) :-
    (   code_type(C, csym)
    ;   C == 0'.
    ),
    !,
    (   C == 0'.
    ->  throw(python(unsupported(operator('.'))))
    ;   memberchk(C, `jJ_`)
    ->  throw(python(unsupported(number_form)))
    ;   throw(python(error(syntax)))
    ).
number_end(_).

base_prefix(0'x, 16).
base_prefix(0'X, 16).
base_prefix(0'o, 8).
base_prefix(0'O, 8).
base_prefix(0'b, 2).
base_prefix(0'B, 2).

base_digit(Base, C, V) :-
    code_type(C, xdigit(V)),
    V < Base.

base_add(Base, V, Acc0, Acc) :-
    Acc is Acc0*Base + V.

%   Grammar: top := expr | expr (',' expr)* [','] (a tuple);
%   expr := unary (('+'|'-') unary)*;
%   unary := ('+'|'-') unary | atom.

py_top(Tree) -->
    py_expr(First),
    (   [punct(0',)]
    ->  py_tuple_rest(Rest),
        { Tree = tuple([First|Rest]) }
    ;   { Tree = First }
    ).

py_tuple_rest([]) -->
    [].
py_tuple_rest([H|T]) -->
    py_expr(H),
    (   [punct(0',)]
    ->  py_tuple_rest(T)
    ;   { T = [] }
    ).

py_expr(Tree) -->
    py_unary(T0),
    py_binary_rest(T0, Tree).

py_binary_rest(T0, Tree) -->
    [punct(Op)],
    { memberchk(Op, `+-`) },
    !,
    py_unary(T1),
    { char_code(OpChar, Op),
      T2 =.. [OpChar, T0, T1]
    },
    py_binary_rest(T2, Tree).
py_binary_rest(Tree, Tree) -->
    [].

py_unary(neg(T)) -->
    [punct(0'-)],
    !,
    py_unary(T).
py_unary(pos(T)) -->
    [punct(0'+)],
    !,
    py_unary(T).
py_unary(T) -->
    py_atom(T).

py_atom(str(S)) -->
    [str(S0)],
    !,
    py_more_strings(S0, S).
py_atom(num(Text, N)) -->
    [num(Text, N)],
    !.
py_atom(name(N)) -->
    [name(N)],
    !,
    (   [punct(0'[)]
    ->  { throw(python(unsupported(subscript))) }
    ;   []
    ).
py_atom(list(Items)) -->
    [punct(0'[)],
    !,
    py_items(Items, 0']).
py_atom(Tree) -->
    [punct(0'{)],
    !,
    (   [punct(0'})]
    ->  { Tree = dict([]) }
    ;   py_expr(First),
        (   [punct(0':)]
        ->  py_expr(V),
            py_dict_rest([First-V|Pairs], Pairs),
            { Tree = dict([First-V|Pairs]) }
        ;   py_items_rest(Rest, 0'}),
            { Tree = set([First|Rest]) }
        )
    ).

py_more_strings(S0, S) -->
    [str(S1)],
    !,
    { string_concat(S0, S1, S2) },
    py_more_strings(S2, S).
py_more_strings(S, S) -->
    [].

py_items([], Close) -->
    [punct(Close)],
    !.
py_items([H|T], Close) -->
    py_expr(H),
    py_items_rest(T, Close).

py_items_rest([], Close) -->
    [punct(Close)],
    !.
py_items_rest(T, Close) -->
    [punct(0',)],
    py_items(T, Close).

py_dict_rest(_, []) -->
    [punct(0'})],
    !.
py_dict_rest(_, Pairs) -->
    [punct(0',)],
    (   [punct(0'})]
    ->  { Pairs = [] }
    ;   py_expr(K),
        [punct(0':)],
        py_expr(V),
        { Pairs = [K-V|Pairs1] },
        py_dict_rest(_, Pairs1)
    ).

%   py_eval(+Tree, -Value): left to right, as Python evaluates.

py_eval(str(S), str(S)).
py_eval(num(Text, N), num(Text, N)).
py_eval(name(Name), Value) :-
    (   py_constant(Name, Value0)
    ->  Value = Value0
    ;   throw(python(error(name)))
    ).
py_eval(list(Items), list(Values)) :-
    maplist(py_eval, Items, Values).
py_eval(tuple(Items), tuple(Values)) :-
    maplist(py_eval, Items, Values).
py_eval(set(Items), set(Values)) :-
    maplist(py_eval, Items, Values0),
    maplist(py_hashable, Values0),
    list_to_set(Values0, Values).
py_eval(dict(Pairs), dict(Values)) :-
    foldl(py_dict_put, Pairs, [], Values).
py_eval(neg(T), Value) :-
    py_eval(T, V),
    py_arith(neg, V, _, Value).
py_eval(pos(T), Value) :-
    py_eval(T, V),
    py_arith(pos, V, _, Value).
py_eval(+(A, B), Value) :-
    py_eval(A, VA),
    py_eval(B, VB),
    py_arith(+, VA, VB, Value).
py_eval(-(A, B), Value) :-
    py_eval(A, VA),
    py_eval(B, VB),
    py_arith(-, VA, VB, Value).

py_constant('True', bool(true)).
py_constant('False', bool(false)).
py_constant('None', none).

py_arith(Op, A, B, num(Text, N)) :-
    (   py_number_value(A, NA),
        (   Op == neg
        ->  Expr = -NA
        ;   Op == pos
        ->  Expr = NA
        ;   py_number_value(B, NB),
            (   Op == (+)
            ->  Expr = NA + NB
            ;   Expr = NA - NB
            )
        )
    ->  catch(N is Expr, error(evaluation_error(_), _), N = inf),
        format(string(Text), "~w", [N])
    ;   Op == (+),
        A = str(SA),
        B = str(SB)
    ->  throw(python(unsupported(string_concatenation(SA, SB))))
    ;   throw(python(crash(type_error)))
    ).

py_number_value(num(_, N), N).
py_number_value(bool(true), 1).
py_number_value(bool(false), 0).

py_dict_put(KTree-VTree, Pairs0, Pairs) :-
    py_eval(KTree, K),
    py_eval(VTree, V),
    py_hashable(K),
    (   nth0(I, Pairs0, K-_)
    ->  nth0(I, Pairs0, _, Rest),
        nth0(I, Pairs, K-V, Rest)
    ;   append(Pairs0, [K-V], Pairs)
    ).

py_hashable(V) :-
    (   ( V = list(_) ; V = dict(_) ; V = set(_) )
    ->  throw(python(crash(unhashable)))
    ;   true
    ).


                 /*******************************
                 *         ROUND TRIPS          *
                 *******************************/

%!  liboro_view(+PythonValue, -LiboroValue) is det.
%
%   What liboro should read for a collection whose exact value is
%   PythonValue (as pyoro reads it), given liboro's own data model:
%   texts through cleanValue, a list of scalars is a set, a list of
%   2-element lists a map, a dict a map whose keys end at their first
%   `:`.  `unrepresentable` for what that model has no place for
%   (nested collections other than pairs, bools, None).

liboro_view(list(Items), View) :-
    !,
    (   Items = [list(_)|_],
        last(Items, list(_))
    ->  (   maplist(scalar_pair, Items, KVs)
        ->  foldl(view_put, KVs, [], Pairs),
            View = map(Pairs)
        ;   View = unrepresentable
        )
    ;   maplist(scalar_text, Items, Texts)
    ->  maplist(liboro_clean, Texts, Cleaned),
        sort(Cleaned, Set),
        View = set(Set)
    ;   View = unrepresentable
    ).
liboro_view(dict(KVs), View) :-
    !,
    (   maplist(dict_token, KVs, Tokens)
    ->  foldl(token_put, Tokens, [], Pairs),
        View = map(Pairs)
    ;   View = unrepresentable
    ).
liboro_view(_, unrepresentable).

scalar_pair(list([K, V]), KT-VT) :-
    scalar_text(K, KT),
    scalar_text(V, VT).

scalar_text(str(S), S).
scalar_text(num(Text, _), Text).

view_put(K-V, Pairs0, Pairs) :-
    liboro_clean(K, Key),
    liboro_clean(V, Value),
    map_put(Key, Value, Pairs0, Pairs).

dict_token(K-V, Token) :-
    scalar_text(K, KT),
    scalar_text(V, VT),
    atomics_to_string([KT, ":", VT], Token).

token_put(Token, Pairs0, Pairs) :-
    map_token(Token, Pairs0, Pairs).

%!  reply_line_problem(+Kind, +Line, -Problem) is semidet.
%
%   Problem is the first way in which the value line Line of a reply
%   (Kind `ok`) or the content line of an event (Kind `event`) fails a
%   real client; fails if both read it.  Checked:
%
%     - one line for pyoro (no raw `\r`) and liboro (no NUL);
%     - neither client aborts (liboro: an escape Boost does not know;
%       pyoro: an exception it does not catch);
%     - a list or map is a Python literal pyoro reads (NameError is
%       allowed: JSON documents with `true` or `null` stay text, as
%       from oro-server), and a quoted string one too unless it holds a
%       backslash (a verbatim plain string, see oro_encode_value/2);
%     - both clients read the same texts: liboro's reading of a list or
%       map equals liboro_view/2 of pyoro's, and liboro's text of a
%       quoted string without backslash equals pyoro's string.

reply_line_problem(_, Line, raw_line_break) :-
    sub_string(Line, _, _, _, "\r"),
    !.
reply_line_problem(Kind, Line, Problem) :-
    liboro_read_line(Line, Liboro),
    pyoro_read_line(Line, Pyoro),
    line_problem(Kind, Line, Liboro, Pyoro, Problem),
    !.

line_problem(_, _, crash(Why), _, liboro_aborts(Why)).
line_problem(_, _, _, crash(Why), pyoro_aborts(Why)).
line_problem(_, _, _, unsupported(What), pyoro_emulation_unsupported(What)).
line_problem(_, Line, _, raw(_), pyoro_cannot_eval) :-
    sub_string(Line, 0, 1, _, First),
    (   memberchk(First, ["[", "{"])
    ->  \+ python_literal(Line, error(name))
    ;   memberchk(First, ["\"", "'"])
    ->  \+ sub_string(Line, _, _, _, "\\")
    ).
line_problem(_, Line, value(LiboroValue), value(PyoroValue),
             clients_disagree(LiboroValue, View)) :-
    (   PyoroValue = str(S),
        sub_string(Line, 0, 1, _, First),
        memberchk(First, ["\"", "'"])
    ->  \+ sub_string(Line, _, _, _, "\\"),
        liboro_clean(Line, LiboroText),
        LiboroText \== S,
        View = str(S)
    ;   ( PyoroValue = list(_) ; PyoroValue = dict(_) )
    ->  liboro_view(PyoroValue, View),
        View \== unrepresentable,
        LiboroValue \== View
    ).
