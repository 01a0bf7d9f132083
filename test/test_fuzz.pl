:- use_module(library(plunit)).
:- use_module(oro_test_support).
:- use_module(oro_test_client).
:- use_module(library(oro)).

/*  Hostile input over real sockets (issue #8): a table of malformed
    requests with their exact replies, and a seeded random fuzzer.

    The fuzzer runs several connections at once, each sending pipelined
    batches that mix

      (a) well-formed `add` requests of fresh statements (on subjects
          fz_<connection>_<n>), recorded when answered `ok`;
      (b) well-formed `remove` (or `retract`) of some of them, and
          `check` of live and removed ones (exact true/false);
      (c) hostile requests whose framing is known, which must each get
          exactly one `error` (two for an `#end#` inserted in a line):
          unknown methods, unbalanced brackets and quotes, deep
          nesting, invalid UTF-8, NUL bytes, `#end#` inside a line, too
          many parameters, bad escapes and literals, patterns in `add`,
          huge integers (ok or error), ...;
      (d) at the end of some batches, bytes that may poison the framing
          (random binary, random text, mutated read-only requests) or a
          request larger than max_request_size.  After poison the
          client sends `\n#end#\n` and a marker request and reads until
          the marker's error (reconnecting if the server closed the
          connection); after a request too large it expects the error
          and reconnects.

    Hostile requests that would add something use fresh subjects too,
    so the final check is exact: the robot's model holds what it held
    before plus the statements of the acknowledged adds minus the
    acknowledged removes -- nothing else.  The server must answer
    throughout and afterwards.

    Sizes: 5 connections x 10,000 requests (50,000) by default;
    8 x 25,000 with ORO_LONG_TESTS=1.  The seed is printed; set
    ORO_FUZZ_SEED=N to send the same requests again (the interleaving
    of the connections still varies).

    Run: cd /work/main && swipl -g run_tests -t halt test/test_fuzz.pl
*/

:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(ordsets)).
:- use_module(library(random)).
:- use_module(library(settings)).
:- use_module(library(oro/oro_store)).


                 /*******************************
                 *            SETUP             *
                 *******************************/

%   The fuzz server: the test ontology alone, with a request size limit
%   of 128 KiB (so requests too large stay cheap) and at most 32
%   parameters.  Settings are read per connection and per request, and
%   restored to their defaults afterwards.

fuzz_max_request_size(131072).
fuzz_max_params(32).

fuzz_start :-
    fuzz_max_request_size(Size),
    fuzz_max_params(Params),
    set_setting(oro_server:max_request_size, Size),
    set_setting(oro_server:max_params, Params),
    test_server_start_testsuite([rebuild_garbage(50)]).  % rebuilds too

fuzz_stop :-
    test_server_stop,
    restore_setting(oro_server:max_request_size),
    restore_setting(oro_server:max_params).

fuzz_long :-
    getenv('ORO_LONG_TESTS', '1').

%   fuzz_sizes(-Connections, -RequestsPerConnection)

fuzz_sizes(Connections, Requests) :-
    (   fuzz_long
    ->  Connections = 8,
        Requests = 25000
    ;   Connections = 5,
        Requests = 10000
    ).

fuzz_seed(Seed) :-
    test_seed('ORO_FUZZ_SEED', Seed).

%   fuzz_store(-Triples): what the robot's model holds (asserted and
%   visible ontology triples), sorted.

fuzz_store(Triples) :-
    findall(rdf(S, P, O), oro_asserted(myself, S, P, O), Triples0),
    sort(Triples0, Triples).

fuzz_iri(Name, IRI) :-
    atom_concat('http://kb.openrobots.org#', Name, IRI).

fuzz_xsd(Type, IRI) :-
    atom_concat('http://www.w3.org/2001/XMLSchema#', Type, IRI).

%   fuzz_diff(+Expected, +Actual, -Diff): Diff is
%   diff(NMissing, SomeMissing, NExtra, SomeExtra), at most 10 of each
%   listed.

fuzz_diff(Expected, Actual, Diff) :-
    test_diff(Expected, Actual, 10, Diff).


                 /*******************************
                 *          THE TABLE           *
                 *******************************/

%   fuzz_case(?Name, -Parts, -Expected): a hostile request (parts for
%   oro_send_data/2) and the kinds of the replies it must get, in order
%   (`error`, `ok`, or `any` of the two).  None changes the store.

fuzz_case(unknown_method, [text("zz_no_such_method\n[a b c]\n#end#\n")], [error]).
fuzz_case(empty_method, [text("#end#\n")], [error]).
fuzz_case(unclosed_set, [text("add\n[fzt_a p o, fzt_b p o\n#end#\n")], [error]).
fuzz_case(braces, [text("add\n{fzt_a p o}\n#end#\n")], [error]).
fuzz_case(two_tokens, [text("add\n[fzt_a p]\n#end#\n")], [error]).
fuzz_case(four_tokens, [text("add\n[fzt_a p o q]\n#end#\n")], [error]).
fuzz_case(open_double_quote, [text("add\n[\"fzt_a p o, fzt_b p o]\n#end#\n")], [error]).
fuzz_case(open_single_quote, [text("add\n[fzt_a 'p o]\n#end#\n")], [error]).
fuzz_case(nested_balanced, [text(Text)], [error]) :-
    fuzz_repeat(5000, "[", Open),
    fuzz_repeat(5000, "]", Close),
    atomics_to_string(["add\n[", Open, "fzt_a p o", Close, "]\n#end#\n"], Text).
fuzz_case(nested_unbalanced, [text(Text)], [error]) :-
    fuzz_repeat(5000, "[", Open),
    atomics_to_string(["add\n[", Open, "fzt_a p o]\n#end#\n"], Text).
fuzz_case(bad_utf8_illegal_byte,
          [text("add\n[fzt_a p "), octets([0xFF]), text("]\n#end#\n")], [error]).
fuzz_case(bad_utf8_overlong,
          [text("add\n[fzt_a p "), octets([0xC0, 0xAF]), text("]\n#end#\n")], [error]).
fuzz_case(bad_utf8_surrogate,
          [text("add\n[fzt_a p "), octets([0xED, 0xA0, 0x80]), text("]\n#end#\n")], [error]).
fuzz_case(bad_utf8_truncated,
          [text("add\n[fzt_a p "), octets([0xE2, 0x82]), text("]\n#end#\n")], [error]).
fuzz_case(bad_utf8_above_max,
          [text("add\n[fzt_a p "), octets([0xF4, 0x90, 0x80, 0x80]), text("]\n#end#\n")], [error]).
fuzz_case(bad_utf8_in_method,
          [text("ad"), octets([0xC3]), text("d\n[fzt_a p o]\n#end#\n")], [error]).
fuzz_case(nul_in_method, [text("add\u0000\n[fzt_a p o]\n#end#\n")], [error]).
fuzz_case(nul_in_statement, [text("add\n[fzt_a\u0000 p]\n#end#\n")], [error]).
fuzz_case(end_inside_set, [text("add\n[fzt_a p o#end#, fzt_b p o]\n#end#\n")], [error, error]).
fuzz_case(end_inside_method, [text("ad#end#d\n[fzt_c p o]\n#end#\n")], [error, error]).
fuzz_case(too_many_parameters, [text(Text)], [error]) :-
    length(Params, 100),
    maplist(=("[fzt_a p o]\n"), Params),
    atomics_to_string(["add\n"|Params], Head),
    string_concat(Head, "#end#\n", Text).
fuzz_case(bad_unicode_escape, [text("add\n[fzt_a p \"\\u12\"]\n#end#\n")], [error]).
fuzz_case(lone_surrogate_escape, [text("add\n[fzt_a p \"\\ud800\"]\n#end#\n")], [error]).
fuzz_case(pattern_in_add, [text("add\n[fzt_a ?p o]\n#end#\n")], [error]).
fuzz_case(bad_typed_literal, [text("add\n[fzt_a p \"x\"^^xsd:int]\n#end#\n")], [error]).
fuzz_case(empty_datatype, [text("add\n[fzt_a p x^^]\n#end#\n")], [error]).
fuzz_case(empty_elements, [text("add\n[,,,]\n#end#\n")], [error]).
fuzz_case(empty_find_variable, [text("find\n\n[?x p o]\n#end#\n")], [error]).
fuzz_case(bad_event_type, [text("registerEvent\nFOO\nON_TRUE\n[fzt_a p o]\n#end#\n")], [error]).
fuzz_case(huge_integer, [text(Text)], [any]) :-
    fuzz_repeat(3000, "9", Digits),
    atomics_to_string(["check\n[fzt_a p ", Digits, "]\n#end#\n"], Text).
fuzz_case(huge_exponent, [text("check\n[fzt_a p 1e999999999]\n#end#\n")], [any]).
fuzz_case(bad_sparql, [text("query\nx\nSELECT ?x WHERE { ?x ?p\n#end#\n")], [error]).
fuzz_case(bad_filter, [text("find\nx\n[?x p ?y]\n[?y > > 3]\n#end#\n")], [error]).

fuzz_repeat(N, Text, Repeated) :-
    length(Parts, N),
    maplist(=(Text), Parts),
    atomics_to_string(Parts, Repeated).

%   fuzz_case_replies(+Conn, +Parts, +N, -Kinds): send Parts, then read N
%   replies and a `check` sent after them (so that a missing or extra
%   reply shows); Kinds are the kinds of all of them.

fuzz_case_replies(Conn, Parts, N, Kinds) :-
    oro_send_data(Conn, Parts),
    oro_send(Conn, check, ["[fzt_sync p o]"]),
    N1 is N + 1,
    length(Replies, N1),
    maplist(fuzz_receive(Conn), Replies),
    maplist(fuzz_kind, Replies, Kinds).

fuzz_receive(Conn, Reply) :-
    oro_receive(Conn, Reply, 30).

fuzz_kind(ok(_), ok) :- !.
fuzz_kind(error(_, _), error) :- !.
fuzz_kind(Other, Other).

%   fuzz_as_expected(+Expected, +Kind0, -Kind): Kind is `any` where
%   `any` is expected and Kind0 is ok or error, else Kind0.

fuzz_as_expected(any, Kind0, Kind) :-
    memberchk(Kind0, [ok, error]),
    !,
    Kind = any.
fuzz_as_expected(_, Kind, Kind).

:- begin_tests(fuzz_cases, [setup(fuzz_start), cleanup(fuzz_stop)]).

test(replies, [forall(fuzz_case(Name, Parts, Expected)),
               true(Name-Kinds == Name-Kinds0)]) :-
    append(Expected, [ok], Kinds0),
    length(Expected, N),
    test_connected(Conn, fuzz_case_replies(Conn, Parts, N, Kinds1)),
    maplist(fuzz_as_expected, Kinds0, Kinds1, Kinds).

test(store_unchanged, [true(Diff == diff(0, [], 0, []))]) :-
    fuzz_store(Before),
    test_connected(Conn,
                   forall(fuzz_case(_, Parts, Expected),
                          ( length(Expected, N),
                            fuzz_case_replies(Conn, Parts, N, _)
                          ))),
    fuzz_store(After),
    fuzz_diff(Before, After, Diff).

%   A request larger than max_request_size: an error, then the
%   connection is closed (the client stops sending: the server drains
%   what it sent and closes).  Nothing of it is added.

test(too_large, [true(Kind-Rest-Diff == error-[end_of_file]-diff(0, [], 0, []))]) :-
    fuzz_store(Before),
    fuzz_max_request_size(Max),
    Size is Max + 1000,
    fuzz_repeat(Size, "x", Big),
    atomics_to_string(["add\n[fzt_big p \"", Big, "\"]\n#end#\n"], Text),
    test_connected(Conn,
                   ( oro_send_data(Conn, [text(Text)]),
                     fuzz_receive(Conn, Reply),
                     oro_half_close(Conn),
                     oro_drain(Conn, Rest, 30)
                   )),
    fuzz_kind(Reply, Kind),
    fuzz_store(After),
    fuzz_diff(Before, After, Diff).

:- end_tests(fuzz_cases).


                 /*******************************
                 *           GENERATORS         *
                 *******************************/

%   A statement is st(Text, Triple): the text sent and the triple it
%   must add, computed here (not by the server's parser).  Fresh names
%   come from a counter threaded through the generators as N0/N.

fuzz_subject(C, N0, N, Text) :-
    N is N0 + 1,
    (   maybe(0.3)
    ->  random_member(Suffix, ["_é", "_日本", "_😀", "_ß", "_Ω"])
    ;   Suffix = ""
    ),
    format(string(Text), "fz_~d_~d~w", [C, N0, Suffix]).

fuzz_statement(C, N0, N, st(Text, rdf(S, P, O))) :-
    fuzz_subject(C, N0, N, SText),
    random_between(0, 9, PI),
    format(string(PText), "fzp~d", [PI]),
    fuzz_object(OText, O),
    format(string(Text), "~w ~w ~w", [SText, PText, OText]),
    atom_string(SName, SText),
    fuzz_iri(SName, S),
    atom_string(PName, PText),
    fuzz_iri(PName, P).

fuzz_object(Text, Term) :-
    random_between(1, 100, R),
    (   R =< 40
    ->  random_between(0, 999, K),
        format(string(Text), "fzo_~d", [K]),
        atom_string(Name, Text),
        fuzz_iri(Name, Term)
    ;   R =< 55
    ->  random_between(-100000, 100000, I),
        format(string(Text), "~d", [I]),
        fuzz_literal(int, Text, Term)
    ;   R =< 65
    ->  random_member(Sign, ["", "-"]),
        random_between(0, 999, I),
        random_between(1, 9, F),
        format(string(Text), "~w~d.~d", [Sign, I, F]),
        fuzz_literal(double, Text, Term)
    ;   R =< 70
    ->  random_member(Text, ["true", "false"]),
        fuzz_literal(boolean, Text, Term)
    ;   random_between(0, 24, Len),
        length(Chars, Len),
        maplist(fuzz_string_char, Chars),
        atomics_to_string(Chars, Content),
        atomics_to_string(["\"", Content, "\""], Text),
        fuzz_literal(string, Content, Term)
    ).

fuzz_literal(Type, Lex, literal(type(IRI, LexAtom))) :-
    fuzz_xsd(Type, IRI),
    atom_string(LexAtom, Lex).

%   Characters of string literals: no quote, backslash, bracket, brace,
%   `#` or `^` (their quirks are ORO's, see ORO-SPEC §2.2).

fuzz_string_char(Char) :-
    random_member(Char, [ "a", "b", "k", "z", "Q", "0", "7", " ", ",", ".",
                          ";", ":", "!", "?", "-", "(", ")", "/", "@", "é",
                          "ü", "ß", "日", "本", "Ω", "😀", "€", "+", "=", "%"
                        ]).

fuzz_statements(C, K, N0, N, Statements) :-
    length(Statements, K),
    foldl(fuzz_fresh_statement(C), Statements, N0, N).

fuzz_fresh_statement(C, Statement, N0, N) :-
    fuzz_statement(C, N0, N, Statement).

%   fuzz_set_text(+Statements, -Text): `[s1, s2]`, with or without a
%   space after the commas.

fuzz_set_text(Statements, Text) :-
    maplist(fuzz_st_text, Statements, Texts),
    random_member(Sep, [", ", ","]),
    atomic_list_concat(Texts, Sep, Inner),
    atomics_to_string(["[", Inner, "]"], Text).

fuzz_st_text(st(Text, _), Text).

%   fuzz_request(+Method, +Params, -Parts): a well-formed request with
%   some variety: method case, CRLF line ends, empty lines before the
%   method, `#end#` with or without a line end after it.

fuzz_request(Method, Params, [text(Text)]) :-
    (   maybe(0.1)
    ->  upcase_atom(Method, M)
    ;   M = Method
    ),
    (   maybe(0.15)
    ->  NL = "\r\n"
    ;   NL = "\n"
    ),
    (   maybe(0.05)
    ->  Lead = NL
    ;   Lead = ""
    ),
    random_member(End, ["#end#\n", "#end#\n", "#end#\n", "#end#", "#end#\r\n"]),
    foldl(fuzz_param_line(NL), Params, Lines, []),
    atomics_to_string([Lead, M, NL|Lines], Head),
    string_concat(Head, End, Text).

fuzz_param_line(NL, Param, [Param, NL|T], T).

%   The state of a client while it builds a batch:
%   g(C, N, Avail, Removed, Seq)
%
%     - C: the connection's number
%     - N: the next fresh name number
%     - Avail: the live statements no item of the batch removes
%     - Removed: statements whose removal was acknowledged
%     - Seq: the next marker number

%   fuzz_item(+G0, -G, -Item): Item is item(Parts, Expect, Effect).

fuzz_item(G0, G, Item) :-
    random_between(1, 100, R),
    (   R =< 35
    ->  fuzz_add_item(G0, G, Item)
    ;   R =< 45
    ->  fuzz_remove_item(G0, G, Item)
    ;   R =< 55
    ->  fuzz_check_item(G0, G, Item)
    ;   R =< 92
    ->  fuzz_hostile_item(G0, G, Item)
    ;   fuzz_lenient_item(G0, G, Item)
    ).

fuzz_add_item(g(C, N0, A, Rm, Q), g(C, N, A, Rm, Q),
              item(Parts, ok_void, add(Statements))) :-
    random_between(1, 4, K),
    fuzz_statements(C, K, N0, N, Statements),
    fuzz_set_text(Statements, Set),
    fuzz_request(add, [Set], Parts).

fuzz_remove_item(G0, G, Item) :-
    G0 = g(C, N0, A0, Rm, Q),
    (   A0 == []
    ->  fuzz_add_item(G0, G, Item)
    ;   random_between(1, 3, K),
        fuzz_take(K, A0, Taken, A),
        Statements0 = Taken,
        (   maybe(0.3)                  % and one that was never added
        ->  fuzz_statement(C, N0, N, Never),
            append(Statements0, [Never], Statements)
        ;   N = N0,
            Statements = Statements0
        ),
        fuzz_set_text(Statements, Set),
        random_member(Method, [remove, remove, retract]),
        fuzz_request(Method, [Set], Parts),
        G = g(C, N, A, Rm, Q),
        Item = item(Parts, ok_void, remove(Taken))
    ).

%   fuzz_take(+K, +List0, -Taken, -List): take up to K random elements.

fuzz_take(0, List, [], List) :-
    !.
fuzz_take(_, [], [], []) :-
    !.
fuzz_take(K, List0, [X|Xs], List) :-
    length(List0, Len),
    random_between(1, Len, I),
    nth1(I, List0, X, List1),
    K1 is K - 1,
    fuzz_take(K1, List1, Xs, List).

fuzz_check_item(g(C, N0, A, Rm, Q), g(C, N, A, Rm, Q), item(Parts, bool(B), none)) :-
    random_between(1, 3, R),
    (   R =:= 1,
        A \== []
    ->  random_member(st(Text, _), A),
        B = true,
        N = N0
    ;   R =:= 2,
        Rm \== []
    ->  random_member(st(Text, _), Rm),
        B = false,
        N = N0
    ;   fuzz_statement(C, N0, N, st(Text, _)),
        B = false
    ),
    format(string(Set), "[~w]", [Text]),
    fuzz_request(check, [Set], Parts).

%   Hostile requests that must get exactly one error (two for an
%   `#end#` inside a line).

fuzz_hostile_item(g(C, N0, A, Rm, Q), g(C, N, A, Rm, Q), item(Parts, errors(E), none)) :-
    random_between(1, 19, Kind),
    fuzz_hostile(Kind, C, N0, N, Parts, E).

fuzz_hostile(1, _, N, N, [text(Text)], 1) :-       % unknown method
    random_between(1, 20, Len),
    length(Chars, Len),
    maplist(fuzz_name_char, Chars),
    random_between(0, 3, NP),
    length(Params, NP),
    maplist(=("[a b c]"), Params),
    atomics_to_string(["zz"|Chars], Method),
    fuzz_request(Method, Params, [text(Text)]).
fuzz_hostile(2, C, N0, N, Parts, 1) :-           % set not closed
    fuzz_some_statements(C, N0, N, Statements),
    fuzz_set_text(Statements, Set),
    sub_string(Set, 0, _, 1, Open),
    fuzz_request(add, [Open], Parts).
fuzz_hostile(3, C, N0, N, Parts, 1) :-           % braces
    fuzz_some_statements(C, N0, N, Statements),
    fuzz_set_text(Statements, Set),
    sub_string(Set, 1, _, 1, Inner),
    atomics_to_string(["{", Inner, "}"], Braces),
    fuzz_request(add, [Braces], Parts).
fuzz_hostile(4, C, N0, N, Parts, 1) :-           % not three tokens
    random_member(K, [1, 2, 4, 5]),
    length(Names, K),
    foldl(fuzz_fresh_subject(C), Names, N0, N),
    atomic_list_concat(Names, ' ', Statement),
    format(string(Set), "[~w]", [Statement]),
    fuzz_request(add, [Set], Parts).
fuzz_hostile(5, C, N0, N, Parts, 1) :-           % an open quote
    fuzz_some_statements(C, N0, N, Statements),
    fuzz_set_text(Statements, Set),
    sub_string(Set, 1, _, 0, Rest),
    (   sub_string(Set, _, _, _, "\"")     % an element could end with it:
    ->  Quote = "'"                         % its quotes would be stripped
    ;   random_member(Quote, ["\"", "'"])
    ),
    atomics_to_string(["[", Quote, Rest], Quoted),
    fuzz_request(add, [Quoted], Parts).
fuzz_hostile(6, C, N0, N, [text(Text)], 1) :-    % deep nesting
    fuzz_statement(C, N0, N, st(Statement, _)),
    random_between(1, 500, Depth),
    fuzz_repeat(Depth, "[", Open),
    (   maybe(0.5)
    ->  fuzz_repeat(Depth, "]", Close)
    ;   random_between(0, Depth, Fewer),
        Closing is Depth - Fewer,
        fuzz_repeat(Closing, "]", Close)
    ),
    atomics_to_string(["add\n[", Open, Statement, Close, "]\n#end#\n"], Text).
fuzz_hostile(7, C, N0, N, Parts, 1) :-           % invalid UTF-8
    fuzz_some_statements(C, N0, N, Statements),
    fuzz_set_text(Statements, Set),
    random_member(Bad, [ [0xFF], [0xFE], [0xC0, 0xAF], [0xC1, 0xBF],
                         [0xED, 0xA0, 0x80], [0xED, 0xBF, 0xBF],
                         [0xE2, 0x82], [0xF0, 0x9F, 0x98], [0x80], [0xBF],
                         [0xF4, 0x90, 0x80, 0x80], [0xF5, 0x80, 0x80, 0x80],
                         [0xF8, 0x88, 0x80, 0x80, 0x80], [0xC3]
                       ]),
    (   maybe(0.8)
    ->  string_length(Set, Len),
        random_between(0, Len, At),
        sub_string(Set, 0, At, After, Before),
        sub_string(Set, At, After, 0, Rest),
        Parts = [text("add\n"), text(Before), octets(Bad), text(Rest),
                 text("\n#end#\n")]
    ;   Parts = [text("ad"), octets(Bad), text("d\n"), text(Set),
                 text("\n#end#\n")]
    ).
fuzz_hostile(8, C, N0, N, [text(Text)], 1) :-    % NUL
    fuzz_subject(C, N0, N, Subject),
    random_member(Template, [ "add\u0000\n[~w p o]\n#end#\n",
                              "\u0000add\n[~w p o]\n#end#\n",
                              "add\n[~w\u0000 p]\n#end#\n",
                              "add\n[~w p\u0000]\n#end#\n"
                            ]),
    format(string(Text), Template, [Subject]).
fuzz_hostile(9, C, N0, N, [text(Text)], 2) :-   % #end# inside the line
    fuzz_some_statements(C, N0, N, Statements),
    fuzz_set_text(Statements, Set),
    string_length(Set, Len),
    Last is Len - 1,
    random_between(1, Last, At),
    sub_string(Set, 0, At, After, Before),
    sub_string(Set, At, After, 0, Rest),
    atomics_to_string(["add\n", Before, "#end#", Rest, "\n#end#\n"], Text).
fuzz_hostile(10, C, N0, N, Parts, 1) :-          % too many parameters
    fuzz_max_params(Max),
    Top is Max + 8,
    random_between(3, Top, NP),
    length(Params, NP),
    foldl(fuzz_one_set(C), Params, N0, N),
    fuzz_request(add, Params, Parts).
fuzz_hostile(11, C, N0, N, Parts, 1) :-          % bad escapes
    fuzz_subject(C, N0, N, Subject),
    random_member(Object, ["\"\\u12\"", "\"\\uZZZZ\"", "\"\\ud800\"",
                           "\"\\udfff x\"", "\"\\u\""]),
    format(string(Set), "[~w p ~w]", [Subject, Object]),
    fuzz_request(add, [Set], Parts).
fuzz_hostile(12, C, N0, N, Parts, 1) :-          % a pattern in add
    fuzz_subject(C, N0, N, Subject),
    random_member(Template, ["[~w ?p o]", "[?s ~w o]", "[~w p ?]"]),
    format(string(Set), Template, [Subject]),
    fuzz_request(add, [Set], Parts).
fuzz_hostile(13, C, N0, N, Parts, 1) :-          % bad typed literals
    fuzz_subject(C, N0, N, Subject),
    random_member(Object, ["\"x\"^^xsd:int", "x^^", "^^", "1.5^^xsd:int",
                           "true^^xsd:int", "\"abc\"^^xsd:double",
                           "\"2\"^^xsd:boolean"]),
    format(string(Set), "[~w p ~w]", [Subject, Object]),
    fuzz_request(add, [Set], Parts).
fuzz_hostile(14, _, N, N, [text("#end#\n")], 1).  % a bare #end#
fuzz_hostile(15, C, N0, N, Parts, 1) :-          % remove, not closed
    fuzz_some_statements(C, N0, N, Statements),
    fuzz_set_text(Statements, Set),
    sub_string(Set, 0, _, 1, Open),
    fuzz_request(remove, [Open], Parts).
fuzz_hostile(16, _, N, N, Parts, 1) :-           % find, empty variable
    fuzz_request(find, ["", "[?x fzp1 o]"], Parts).
fuzz_hostile(17, C, N0, N, Parts, 1) :-          % bad event descriptors
    fuzz_subject(C, N0, N, Subject),
    format(string(Set), "[~w p o]", [Subject]),
    random_member(Type-Trigger, ["FOO"-"ON_TRUE", "FACT_CHECKING"-"ON_MAYBE",
                                 ""-"", "NEW_INSTANCE"-"ON_TRUE"]),
    fuzz_request(registerEvent, [Type, Trigger, Set], Parts).
fuzz_hostile(18, _, N, N, Parts, 1) :-           % clearEvent, unknown id
    random_member(Id, ["0c6f3a4e-0000-4000-8000-000000000000", "not-a-uuid", ""]),
    fuzz_request(clearEvent, [Id], Parts).
fuzz_hostile(19, C, N0, N, Parts, 1) :-          % a set that is no set
    fuzz_subject(C, N0, N, Subject),
    random_member(Template, ["~w p o", "(~w p o)", "~w p o]", "<~w p o>"]),
    format(string(Param), Template, [Subject]),
    fuzz_request(add, [Param], Parts).

fuzz_fresh_subject(C, Subject, N0, N) :-
    fuzz_subject(C, N0, N, Subject).

fuzz_some_statements(C, N0, N, Statements) :-
    random_between(1, 3, K),
    fuzz_statements(C, K, N0, N, Statements).

fuzz_one_set(C, Set, N0, N) :-
    fuzz_statement(C, N0, N, st(Text, _)),
    format(string(Set), "[~w]", [Text]).

fuzz_name_char(Char) :-
    random_member(Char, ["a", "q", "Z", "0", "_", ".", ":", "é", "-", ";"]).

%   Requests that may be answered ok or error, but with exactly one
%   reply, and that change nothing.

fuzz_lenient_item(g(C, N0, A, Rm, Q), g(C, N, A, Rm, Q), item(Parts, ok_or_error, none)) :-
    fuzz_subject(C, N0, N, Subject),
    (   maybe(0.02)                     % lookup scans all the resources:
    ->  Kind = 3                        % keep it rare
    ;   random_member(Kind, [1, 2, 4, 5, 6, 7])
    ),
    fuzz_lenient(Kind, Subject, Parts).

fuzz_lenient(1, Subject, Parts) :-               % huge integers
    random_between(10, 1000, Len),
    fuzz_repeat(Len, "9", Digits),
    random_member(Sign, ["", "-"]),
    format(string(Set), "[~w fzp1 ~w~w]", [Subject, Sign, Digits]),
    fuzz_request(check, [Set], Parts).
fuzz_lenient(2, Subject, Parts) :-               % odd numbers
    random_member(Number, ["1e999999999", "-1.5e-400", "NaN", "Infinity",
                           "0x10", "1_000", "1.", ".5", "1e", "--1", "+7"]),
    format(string(Set), "[~w fzp1 ~w]", [Subject, Number]),
    fuzz_request(check, [Set], Parts).
fuzz_lenient(3, _, Parts) :-                     % lookup of junk
    random_between(0, 40, Len),
    length(Chars, Len),
    maplist(fuzz_junk_char, Chars),
    atomics_to_string(Chars, Text),
    fuzz_request(lookup, [Text], Parts).
fuzz_lenient(4, Subject, Parts) :-               % labels of unknown names
    random_member(Method, [getLabel, getInfos, getClassesOf, getResourceDetails]),
    fuzz_request(Method, [Subject], Parts).
fuzz_lenient(5, Subject, Parts) :-               % broken SPARQL
    random_member(Query, [ "SELECT ?x WHERE { ?x ?p",
                           "SELECT WHERE { }",
                           "ASK { ?x <http://a> \"unterminated }",
                           "SELECT ?x WHERE { ?x ?p ?o FILTER ( ?o > ) }",
                           "SELECT ?x WHERE { ?x :fzp1 ?o } LIMIT -1",
                           "PREFIX : <bad SELECT ?x",
                           "SELECT ?x WHERE { ?x ?p ?o } ORDER BY"
                         ]),
    fuzz_request(query, [Subject, Query], Parts).
fuzz_lenient(6, Subject, Parts) :-               % broken filters
    random_member(Filter, ["[?y >]", "[regex(?y, \"(\")]", "[?y = ]",
                           "[((((?y)]", "[?y = \"x\"^^]", "[]"]),
    format(string(Pattern), "[~w fzp1 ?y]", [Subject]),
    fuzz_request(find, ["y", Pattern, Filter], Parts).
fuzz_lenient(7, Subject, Parts) :-               % weird names
    random_member(Name, ["<>", ":", "::", "oro:", "rdf:", "<http://a b>",
                         "http://x.org/a#", "_:b1", "*", "owl:Nothing"]),
    format(string(Set), "[~w fzp1 ~w]", [Subject, Name]),
    fuzz_request(check, [Set], Parts).

fuzz_junk_char(Char) :-
    random_member(Char, ["a", " ", "\t", "\"", "'", "[", "]", "{", "}", "?",
                         "\\", "é", "😀", "\u0001", "\u0000", ",", "*", "%"]).

%   Items that end a batch: poison, or a request too large.

fuzz_terminal_item(g(C, N0, A, Rm, Q0), g(C, N, A, Rm, Q), Item) :-
    Q is Q0 + 1,
    format(string(Marker), "zzsync_~d_~d", [C, Q0]),
    atomics_to_string(["\n#end#\n", Marker, "\n#end#\n"], Sync),
    (   maybe(0.1)
    ->  fuzz_too_large(C, N0, N, Parts),
        Item = item(Parts, too_large, none)
    ;   N = N0,
        fuzz_poison(C, Poison),
        append(Poison, [text(Sync)], Parts),
        Item = item(Parts, sync(Marker), none)
    ).

fuzz_too_large(C, N0, N, [text(Text)]) :-
    fuzz_subject(C, N0, N, Subject),
    fuzz_max_request_size(Max),
    random_between(1, 20000, Extra),
    Size is Max + Extra,
    fuzz_repeat(Size, "x", Big),
    atomics_to_string(["add\n[", Subject, " fzp1 \"", Big, "\"]\n#end#\n"], Text).

fuzz_poison(C, Parts) :-
    random_between(1, 100, R),
    (   R =< 30
    ->  random_between(1, 2000, Len),
        length(Bytes, Len),
        maplist(fuzz_byte, Bytes),
        Parts = [octets(Bytes)]
    ;   R =< 55
    ->  random_between(1, 500, Len),
        length(Chars, Len),
        maplist(fuzz_poison_char, Chars),
        atomics_to_string(Chars, Text),
        Parts = [text(Text)]
    ;   R =< 99
    ->  fuzz_read_only_request(C, Text),
        string_codes(Text, Codes0),
        phrase(fuzz_utf8(Codes0), Bytes0),
        random_between(1, 4, K),
        fuzz_mutate(K, Bytes0, Bytes),
        Parts = [octets(Bytes)]
    ;   Parts = [text("close\n#end#\n")]
    ).

fuzz_byte(Byte) :-
    random_between(0, 255, Byte).

fuzz_poison_char(Char) :-
    random_member(Char, ["a", "d", "\n", "\n", "\r", "[", "]", "\"", "'", "{",
                         "}", "#", "end", "#end", "?", " ", ",", "\\", "\u0000",
                         "é", "help", "add", "find", "x y z"]).

%   Read-only requests to mutate: whatever the mutation, they cannot
%   become a change (no method of the table is one or two edits from
%   them), and their patterns have one pattern only.

fuzz_read_only_request(C, Text) :-
    random_between(0, 999, K),
    random_member(Template, [ "check\n[fz_~d_~d fzp1 fzo_1]\n#end#\n",
                              "find\nx\n[fz_~d_~d fzp2 ?x]\n#end#\n",
                              "lookup\nfz_~d_~d\n#end#\n",
                              "getInfos\nfz_~d_~d\n#end#\n",
                              "find\nx\n[?x fzp3 fz_~d_~d]\n[?x != 3]\n#end#\n"
                            ]),
    format(string(Text), Template, [C, K]).

fuzz_utf8([]) -->
    [].
fuzz_utf8([C|Cs]) -->
    fuzz_utf8_code(C),
    fuzz_utf8(Cs).

fuzz_utf8_code(C) -->
    (   { C < 0x80 }
    ->  [C]
    ;   { C < 0x800 }
    ->  { B1 is 0xC0 \/ (C >> 6), B2 is 0x80 \/ (C /\ 0x3F) },
        [B1, B2]
    ;   { C < 0x10000 }
    ->  { B1 is 0xE0 \/ (C >> 12), B2 is 0x80 \/ ((C >> 6) /\ 0x3F),
          B3 is 0x80 \/ (C /\ 0x3F) },
        [B1, B2, B3]
    ;   { B1 is 0xF0 \/ (C >> 18), B2 is 0x80 \/ ((C >> 12) /\ 0x3F),
          B3 is 0x80 \/ ((C >> 6) /\ 0x3F), B4 is 0x80 \/ (C /\ 0x3F) },
        [B1, B2, B3, B4]
    ).

%   fuzz_mutate(+K, +Bytes0, -Bytes): K random edits.

fuzz_mutate(0, Bytes, Bytes) :-
    !.
fuzz_mutate(K, Bytes0, Bytes) :-
    length(Bytes0, Len),
    random_between(0, Len, At),
    length(Before, At),
    append(Before, After, Bytes0),
    random_between(1, 6, Op),
    fuzz_mutation(Op, Before, After, Bytes1),
    K1 is K - 1,
    fuzz_mutate(K1, Bytes1, Bytes).

fuzz_mutation(1, Before, [_|After], Bytes) :-    % replace a byte
    !,
    fuzz_byte(B),
    append(Before, [B|After], Bytes).
fuzz_mutation(2, Before, After, Bytes) :-        % insert random bytes
    !,
    random_between(1, 8, N),
    length(New, N),
    maplist(fuzz_byte, New),
    append([Before, New, After], Bytes).
fuzz_mutation(3, Before, After, Bytes) :-        % delete a range
    !,
    random_between(1, 8, N),
    (   length(Dropped, N),
        append(Dropped, Rest, After)
    ->  true
    ;   Rest = []
    ),
    append(Before, Rest, Bytes).
fuzz_mutation(4, Before, After, Bytes) :-        % duplicate a range
    !,
    random_between(1, 16, N),
    (   length(Dup, N),
        append(Dup, _, After)
    ->  true
    ;   Dup = After
    ),
    append([Before, Dup, After], Bytes).
fuzz_mutation(5, Before, After, Bytes) :-        % insert a special
    !,
    random_member(Special, ["#end#", "\n", "\r", "\r\n", "\u0000", "[", "]",
                            "\"", "'", "#end#\n", "help\n"]),
    string_codes(Special, New),
    append([Before, New, After], Bytes).
fuzz_mutation(_, Before, _, Before).             % truncate


                 /*******************************
                 *            CLIENTS           *
                 *******************************/

%   fuzz_client(+Queue, +Port, +C, +Seed, +Quota): run connection C and
%   send result(C, Triples, Problems, Sent) to Queue: Triples are the
%   statements its acknowledged adds left (minus acknowledged
%   removes), Problems the replies that were not as expected (at most
%   20), Sent the number of requests sent.

fuzz_client(Queue, Port, C, Seed, Quota) :-
    ClientSeed is Seed + C,
    set_random(seed(ClientSeed)),
    catch(fuzz_session(Port, C, Quota, Live, Problems, Sent), E,
          ( Live = [],
            Sent = 0,
            Problems = [exception(E)]
          )),
    maplist(fuzz_st_triple, Live, Triples),
    thread_send_message(Queue, result(C, Triples, Problems, Sent)).

fuzz_st_triple(st(_, Triple), Triple).

fuzz_session(Port, C, Quota, Live, Problems, Sent) :-
    oro_connect(Port, Conn0, [nodelay(true)]),
    fuzz_batches(Port, C, Quota, s(Conn0, 0, pool([], []), [], 0, 0, []), S),
    S = s(Conn, _, pool(Active, Settled), _, _, Sent, Problems0),
    append(Active, Settled, Live),
    oro_disconnect(Conn),
    reverse(Problems0, Problems1),
    test_first(20, Problems1, Problems).

%   The state of a client between batches:
%   s(Conn, N, pool(Active, Settled), Removed, Seq, Sent, Problems), N
%   the next fresh name number; the live statements are Active (at most
%   a few hundred, which items remove and check) and Settled (kept
%   till the end, so that the cost of an item does not grow with the
%   run); Removed the last 200 removed statements (all lists of st/2);
%   Seq the next marker
%   number, Problems newest first.  The loop stops at the quota, or
%   after a reply that leaves the client unable to tell which reply
%   answers which request (a problem stop(_)).

fuzz_batches(Port, C, Quota, S0, S) :-
    S0 = s(Conn, N0, Pool0, Removed, Seq0, Sent0, Problems0),
    fuzz_settle(Pool0, Pool),
    Pool = pool(Active, _),
    (   Sent0 >= Quota
    ->  S = S0
    ;   Problems0 = [stop(_)-_|_]
    ->  S = S0
    ;   random_between(5, 60, Max),
        fuzz_batch_items(Max, 0, g(C, N0, Active, Removed, Seq0), G1, Items0),
        (   maybe(0.1)
        ->  fuzz_terminal_item(G1, G, Terminal),
            append(Items0, [Terminal], Items)
        ;   G = G1,
            Items = Items0
        ),
        G = g(_, N, _, _, Seq),
        length(Items, K),
        Sent is Sent0 + K,
        findall(P, ( member(item(Ps, _, _), Items), member(P, Ps) ), Parts),
        catch(oro_send_data(Conn, Parts), E, true),
        (   var(E)
        ->  foldl(fuzz_reply(Port),
                  Items, s(Conn, N, Pool, Removed, Seq, Sent, Problems0), S1),
            fuzz_batches(Port, C, Quota, S1, S)
        ;   S = s(Conn, N, Pool, Removed, Seq, Sent,
                  [stop(send_failed(E))-""|Problems0])
        )
    ).

%   fuzz_settle(+Pool0, -Pool): between batches, keep the newest 200
%   active statements when there are more than 400.

fuzz_settle(pool(A0, S0), pool(A, S)) :-
    length(A0, Len),
    (   Len > 400
    ->  length(A, 200),
        append(A, Older, A0),
        append(Older, S0, S)
    ;   A = A0,
        S = S0
    ).

%   fuzz_batch_items(+Max, +Bytes, +G0, -G, -Items): up to Max items,
%   about 48 KB at most, so that the replies (which may quote the
%   requests) fit in the socket buffers while the batch is written.
%   Statements an item removes are taken out of the available ones of
%   G, so no later item of the batch uses them.

fuzz_batch_items(Max, Bytes0, G0, G, Items) :-
    (   (   Max =< 0
        ;   Bytes0 > 48000
        )
    ->  G = G0,
        Items = []
    ;   fuzz_item(G0, G1, Item),
        Item = item(Parts, _, _),
        foldl(fuzz_part_size, Parts, Bytes0, Bytes1),
        Max1 is Max - 1,
        Items = [Item|Items1],
        fuzz_batch_items(Max1, Bytes1, G1, G, Items1)
    ).

fuzz_part_size(text(T), B0, B) :-
    string_length(T, L),
    B is B0 + L.
fuzz_part_size(octets(Bytes), B0, B) :-
    length(Bytes, L),
    B is B0 + L.

%   fuzz_reply(+Port, +Item, +S0, -S): read the replies of Item and
%   apply its effect if they are as expected.

fuzz_reply(_, _, S0, S) :-
    S0 = s(_, _, _, _, _, _, [stop(_)-_|_]),
    !,
    S = S0.
fuzz_reply(Port, item(Parts, Expect, Effect), S0, S) :-
    S0 = s(Conn, N, Live0, Removed0, Seq, Sent, Problems0),
    fuzz_expect(Expect, Port, Conn, Conn1, Outcome),
    (   Outcome == ok
    ->  fuzz_effect(Effect, Live0, Live, Removed0, Removed),
        Problems = Problems0
    ;   Live = Live0,
        Removed = Removed0,
        fuzz_short_parts(Parts, Short),
        Problems = [Outcome-Short|Problems0]
    ),
    S = s(Conn1, N, Live, Removed, Seq, Sent, Problems).

fuzz_short_parts(Parts, Short) :-
    findall(T, ( member(P, Parts),
                 (   P = text(T)
                 ->  true
                 ;   T = "<bytes>"
                 )
               ), Ts),
    atomics_to_string(Ts, Text),
    string_length(Text, Len),
    (   Len > 300
    ->  sub_string(Text, 0, 300, _, Short)
    ;   Short = Text
    ).

fuzz_effect(none, P, P, R, R).
fuzz_effect(add(Statements), pool(A0, S), pool(A, S), R, R) :-
    append(Statements, A0, A).
fuzz_effect(remove(Statements), pool(A0, S), pool(A, S), R0, R) :-
    subtract(A0, Statements, A),
    append(Statements, R0, R1),
    test_first(200, R1, R).

%   fuzz_expect(+Expect, +Port, +Conn0, -Conn, -Outcome): read what
%   Expect says; Outcome is `ok` or a problem term.  Conn is Conn0, or a
%   new connection after the server closed Conn0 (poison, too large).
%   A problem stop(...) stops the client.

fuzz_expect(ok_void, _, Conn, Conn, Outcome) :-
    fuzz_receive(Conn, Reply),
    (   Reply == ok("")
    ->  Outcome = ok
    ;   fuzz_in_sync(Reply)
    ->  Outcome = rejected(Reply)
    ;   Outcome = stop(Reply)
    ).
fuzz_expect(bool(B), _, Conn, Conn, Outcome) :-
    fuzz_receive(Conn, Reply),
    atom_string(B, Text),
    (   Reply == ok(Text)
    ->  Outcome = ok
    ;   fuzz_in_sync(Reply)
    ->  Outcome = wrong_check(B, Reply)
    ;   Outcome = stop(Reply)
    ).
fuzz_expect(errors(N), _, Conn, Conn, Outcome) :-
    length(Replies, N),
    maplist(fuzz_receive(Conn), Replies),
    (   maplist(fuzz_is_error, Replies)
    ->  Outcome = ok
    ;   Outcome = stop(not_errors(Replies))
    ).
fuzz_expect(ok_or_error, _, Conn, Conn, Outcome) :-
    fuzz_receive(Conn, Reply),
    (   fuzz_in_sync(Reply)
    ->  Outcome = ok
    ;   Outcome = stop(Reply)
    ).
fuzz_expect(sync(Marker), Port, Conn0, Conn, Outcome) :-
    fuzz_sync(Marker, 0, Port, Conn0, Conn, Outcome).
fuzz_expect(too_large, Port, Conn0, Conn, Outcome) :-
    fuzz_receive(Conn0, Reply),
    (   Reply = error(_, Message),
        sub_string(Message, _, _, _, "larger")
    ->  Outcome = ok
    ;   Outcome = stop(not_too_large(Reply))
    ),
    oro_disconnect(Conn0),
    oro_connect(Port, Conn, [nodelay(true)]).

fuzz_in_sync(ok(_)).
fuzz_in_sync(error(_, _)).

fuzz_is_error(error(_, _)).

%   After poison: replies of whatever the poison framed (ok, error,
%   `Closing now!`) until the marker's error; a closed connection is
%   reopened.

fuzz_sync(Marker, Count, Port, Conn0, Conn, Outcome) :-
    fuzz_receive(Conn0, Reply),
    (   Reply = error(_, Message),
        sub_string(Message, _, _, _, Marker)
    ->  Conn = Conn0,
        Outcome = ok
    ;   Reply == end_of_file
    ->  oro_disconnect(Conn0),
        oro_connect(Port, Conn, [nodelay(true)]),
        Outcome = ok
    ;   Count > 10000
    ->  Conn = Conn0,
        Outcome = stop(no_marker(Marker))
    ;   (   fuzz_in_sync(Reply)
        ;   Reply == closing
        )
    ->  Count1 is Count + 1,
        fuzz_sync(Marker, Count1, Port, Conn0, Conn, Outcome)
    ;   Conn = Conn0,
        Outcome = stop(Reply)
    ).

%   fuzz_run(+Port, +Connections, +Quota, +Seed, -Results): run
%   the clients at once, each in a thread, within 600 s in all.

fuzz_run(Port, Connections, Quota, Seed, Results) :-
    message_queue_create(Queue),
    call_cleanup(
        ( forall(between(1, Connections, C),
                 thread_create(fuzz_thread(Queue, Port, C, Seed, Quota), _,
                               [detached(true)])),
          get_time(Now),
          Deadline is Now + 600,
          length(Results, Connections),
          maplist(fuzz_result(Queue, Deadline), Results)
        ),
        message_queue_destroy(Queue)).

fuzz_thread(Queue, Port, C, Seed, Quota) :-
    fuzz_client(Queue, Port, C, Seed, Quota).

fuzz_result(Queue, Deadline, Result) :-
    get_time(Now),
    Left is max(0, Deadline - Now),
    (   thread_get_message(Queue, Result0, [timeout(Left)])
    ->  Result = Result0
    ;   Result = result(none, [], [stop(deadline_passed)], unknown)
    ).

fuzz_problems(result(C, _, Problems, _), C-First) :-
    test_first(5, Problems, First).

fuzz_sent(result(_, _, _, Sent), Sent).

fuzz_triples(result(_, Triples, _, _), Triples).

:- begin_tests(fuzz_random, [setup(fuzz_start), cleanup(fuzz_stop)]).

test(random_requests,
     [ true(Problems-Diff-Answer == NoProblems-diff(0, [], 0, [])-ok("true")) ]) :-
    fuzz_seed(Seed),
    fuzz_sizes(Connections, Quota),
    format(user_error,
           "~N% test_fuzz: seed ~d, ~d connections x ~D requests \c
            (ORO_FUZZ_SEED=~d replays it)~n",
           [Seed, Connections, Quota, Seed]),
    test_server_port(Port),
    fuzz_store(Before),
    fuzz_run(Port, Connections, Quota, Seed, Results),
    maplist(fuzz_problems, Results, Problems0),
    msort(Problems0, Problems),
    findall(C-[], between(1, Connections, C), NoProblems),
    maplist(fuzz_sent, Results, Sents),
    sum_list(Sents, Sent),
    assertion(Sent >= Connections * Quota),
    maplist(fuzz_triples, Results, TripleLists),
    append([Before|TripleLists], Expected0),
    sort(Expected0, Expected),
    fuzz_store(After),
    fuzz_diff(Expected, After, Diff),
    test_call(check, ["[baboon rdf:type Animal]"], Answer).

:- end_tests(fuzz_random).
