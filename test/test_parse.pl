/*  Tests for library(oro/oro_parse): parameter decoding (ORO-SPEC §2),
    statements and literals (§4.2, §4.3) and the decode vectors of §13.14.

    Run: cd /work/main && swipl -g "run_tests" -t halt test/test_parse.pl
*/

:- use_module(library(plunit)).
:- use_module(oro_test_support).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(oro/parse/oro_parse)).

%   obj(+ObjectText, -Object): parse `s p ObjectText`, return the object.

obj(Text, Object) :-
    atomics_to_string(["s p ", Text], Statement),
    oro_parse_statement(Statement, rdf(_, _, Object)).

oro(Local, IRI) :-
    rdf_global_id(oro:Local, IRI).

spec_tokens("{},f\\'\\, \\}, [r ,t,\\]\" \",r ] ,a").


                 /*******************************
                 *           TOKENIZER          *
                 *******************************/

:- begin_tests(tokenizer).

test(spec_vector_comma, true(Tokens == ["{}", "f\\'\\", " \\}",
                                        " [r ,t,\\]\" \",r ] ", "a"])) :-
    spec_tokens(Text),
    oro_tokenize(Text, ',', Tokens).
test(spec_vector_comma_count, true(N == 5)) :-
    spec_tokens(Text),
    oro_tokenize(Text, ',', Tokens),
    length(Tokens, N).
test(spec_vector_space, true(Tokens == ["{},f\\'\\,", "\\},",
                                        "[r ,t,\\]\" \",r ]", ",a"])) :-
    spec_tokens(Text),
    oro_tokenize(Text, ' ', Tokens).
test(spec_vector_space_count, true(N == 4)) :-
    spec_tokens(Text),
    oro_tokenize(Text, ' ', Tokens),
    length(Tokens, N).
test(empty_text, true(Tokens == [""])) :-
    oro_tokenize("", ',', Tokens).
test(empty_tokens_kept, true(Tokens == ["a", "", "b", ""])) :-
    oro_tokenize("a,,b,", ',', Tokens).
test(two_spaces, true(Tokens == ["a", "", "b"])) :-
    oro_tokenize("a  b", ' ', Tokens).
test(double_quotes_protect, true(Tokens == ["\"a,b\"", "c"])) :-
    oro_tokenize("\"a,b\",c", ',', Tokens).
test(single_quotes_protect, true(Tokens == ["'a b'", "c"])) :-
    oro_tokenize("'a b' c", ' ', Tokens).
test(brackets_and_braces, true(Tokens == ["[a,b]", "{c,d}", "e"])) :-
    oro_tokenize("[a,b],{c,d},e", ',', Tokens).
test(nested_brackets, true(Tokens == ["[[a,b],[c]]", "d"])) :-
    oro_tokenize("[[a,b],[c]],d", ',', Tokens).
test(apostrophe_quirk, true(Tokens == ["\"it's\", b"])) :-
    oro_tokenize("\"it's\", b", ',', Tokens).
test(escaped_apostrophe, true(Tokens == ["\"it\\'s\"", " b"])) :-
    oro_tokenize("\"it\\'s\", b", ',', Tokens).
test(escaped_quote_not_counted, true(Tokens == ["a\\\"", "b"])) :-
    oro_tokenize("a\\\",b", ',', Tokens).
test(escaped_delimiter_still_splits, true(Tokens == ["a\\", "b"])) :-
    oro_tokenize("a\\,b", ',', Tokens).
test(unbalanced_closer_quirk, true(Tokens == ["a],b"])) :-
    oro_tokenize("a],b", ',', Tokens).
test(atom_text, true(Tokens == ["a", "b"])) :-
    oro_tokenize('a,b', ',', Tokens).
test(delimiter_code, true(Tokens == ["a", "b"])) :-
    oro_tokenize("a b", 0' , Tokens).
test(delimiter_string, true(Tokens == ["a", "b"])) :-
    oro_tokenize("a;b", ";", Tokens).
test(bad_delimiter, error(domain_error(oro_delimiter, ab))) :-
    oro_tokenize("a,b", ab, _).
test(bad_text, error(type_error(text, 42))) :-
    oro_tokenize(42, ',', _).

:- end_tests(tokenizer).


                 /*******************************
                 *          CLEAN VALUE         *
                 *******************************/

:- begin_tests(clean_value).

test(bare, true(S == "toto")) :-
    oro_clean_value("toto", S).
test(double_quoted, true(S == "toto")) :-
    oro_clean_value("\"toto\"", S).
test(single_quoted_newline, true(S == "to\nto")) :-
    oro_clean_value("'to\\nto'", S).
test(inner_single_quotes, true(S == "toto 'aime' tata")) :-
    oro_clean_value("'toto 'aime' tata'", S).
test(escaped_outer_quotes, true(S == "\"toto \"aime\" tata\"")) :-
    oro_clean_value("\\\"toto \"aime\" tata\\\"", S).
test(escaped_inner_quotes, true(S == "toto \"aime\" tata")) :-
    oro_clean_value("\"toto \\\"aime\\\" tata\"", S).
test(decode_1_as_string, true(S == "1")) :-           % §13.14
    oro_clean_value("1", S).
test(null_stays, true(S == "null")) :-
    oro_clean_value("null", S).
test(quoted_null_stays, true(S == "null")) :-
    oro_clean_value("\"null\"", S).
test(trim, true(S == "a b")) :-
    oro_clean_value(" \t a b \r\n", S).
test(trim_then_unquote, true(S == " a ")) :-
    oro_clean_value("  \" a \"  ", S).
test(one_pair_only, true(S == "\"a\"")) :-
    oro_clean_value("\"\"a\"\"", S).
test(mismatched_quotes_kept, true(S == "\"abc'")) :-
    oro_clean_value("\"abc'", S).
test(lone_quote_kept, true(S == "\"")) :-
    oro_clean_value("\"", S).
test(empty_quotes, true(S == "")) :-
    oro_clean_value("''", S).
test(empty, true(S == "")) :-
    oro_clean_value("", S).
test(java_escapes, true(S == "\\'\"\r\f\t\n\b")) :-
    oro_clean_value("\\\\\\'\\\"\\r\\f\\t\\n\\b", S).
test(other_escape_drops_backslash, true(S == "xq")) :-
    oro_clean_value("\\x\\q", S).
test(trailing_backslash_kept, true(S == "a\\")) :-
    oro_clean_value("a\\", S).
test(unicode_escape, true(S == "caf\u00e9")) :-
    oro_clean_value("caf\\u00E9", S).
test(surrogate_pair, true(Codes == [0x1F600])) :-
    oro_clean_value("\\uD83D\\uDE00", S),
    string_codes(S, Codes).
test(atom_in_string_out, true(S == "toto")) :-
    oro_clean_value('\'toto\'', S).
test(short_unicode, error(syntax_error(oro_unicode_escape("ab\\u12")))) :-
    oro_clean_value("ab\\u12", _).
test(bad_unicode, error(syntax_error(oro_unicode_escape("\\uzz00")))) :-
    oro_clean_value("\\uzz00", _).
test(lone_high_surrogate,
     error(syntax_error(oro_unicode_escape("\\ud800abc")))) :-
    oro_clean_value("\\ud800abc", _).
test(lone_low_surrogate, error(syntax_error(oro_unicode_escape("\\udc00")))) :-
    oro_clean_value("\\udc00", _).
test(reversed_pair, error(syntax_error(oro_unicode_escape(_)))) :-
    oro_clean_value("\\uDE00\\uD83D", _).
test(not_text, error(type_error(text, f(x)))) :-
    oro_clean_value(f(x), _).

:- end_tests(clean_value).


                 /*******************************
                 *          COLLECTIONS         *
                 *******************************/

:- begin_tests(collections).

test(empty_text_set, true(E == [])) :-
    oro_parse_collection(set, "", E).
test(empty_text_list, true(E == [])) :-              % [QUIRK] fixed
    oro_parse_collection(list, "", E).
test(null_any_case, all(T-E == ["null"-[], "NULL"-[], "Null"-[], nUlL-[]])) :-
    member(T, ["null", "NULL", "Null", nUlL]),
    oro_parse_collection(set, T, E).
test(empty_brackets, true(E == [])) :-               % §13.14
    oro_parse_collection(set, "[]", E).
test(empty_brackets_list, true(E == [])) :-          % §13.14
    oro_parse_collection(list, "[]", E).
test(space_in_brackets, true(E == [""])) :-          % [QUIRK]
    oro_parse_collection(set, "[ ]", E).
test(quoted_elements, true(E == ["toto", "tata"])) :- % §13.14
    oro_parse_collection(set, "[\"toto\",\"tata\"]", E).
test(bare_elements_trimmed, true(E == ["a", "b", "c"])) :-
    oro_parse_collection(list, "[a, b ,c]", E).
test(set_drops_duplicates, true(E == ["a", "b"])) :-
    oro_parse_collection(set, "[a, \"b\", 'a', b]", E).
test(list_keeps_order_and_duplicates, true(E == ["b", "a", "b"])) :-
    oro_parse_collection(list, "[b,a,b]", E).
test(liboro_style, true(E == ["a", "b \"c\""])) :-
    oro_parse_collection(set, "[\"a\",\"b \\\"c\\\"\"]", E).
test(pyoro_style, true(E == ["a b c", "d e \"f\""])) :-
    oro_parse_collection(list, "['a b c', 'd e \"f\"']", E).
test(telnet_style, true(E == ["human rdf:type Human",
                              "human rdfs:label \"Ramses\""])) :-
    oro_parse_collection(list,
                         "[human rdf:type Human, human rdfs:label \"Ramses\"]",
                         E).
test(nested_stays_string, true(E == ["[a,b]", "c"])) :-
    oro_parse_collection(list, "[[a,b], c]", E).
test(apostrophe_quirk, true(E == ["\"it's\", b"])) :-
    oro_parse_collection(list, "[\"it's\", b]", E).
test(escaped_apostrophe, true(E == ["it's", "b"])) :-
    oro_parse_collection(list, "[\"it\\'s\", b]", E).
test(atom_text, true(E == ["a"])) :-
    oro_parse_collection(set, '[a]', E).
test(leading_space, error(type_error(oro_collection, " [a]"))) :-
    oro_parse_collection(set, " [a]", _).
test(trailing_space, error(type_error(oro_collection, "[a] "))) :-
    oro_parse_collection(set, "[a] ", _).
test(braces_as_set, error(type_error(oro_collection, "{}"))) :- % §13.14
    oro_parse_collection(set, "{}", _).
test(unframed, error(type_error(oro_collection, "a,b"))) :-
    oro_parse_collection(list, "a,b", _).
test(open_only, error(type_error(oro_collection, "["))) :-
    oro_parse_collection(list, "[", _).
test(bad_kind, error(domain_error(oneof([set, list]), bag))) :-
    oro_parse_collection(bag, "[]", _).
test(bad_element_escape, error(syntax_error(oro_unicode_escape(" \\u1")))) :-
    oro_parse_collection(list, "[a, \\u1]", _).

:- end_tests(collections).


                 /*******************************
                 *              MAP             *
                 *******************************/

:- begin_tests(map).

test(empty, true(P == [])) :-                        % §13.14
    oro_parse_map("{}", P).
test(spec_vector, true(P == ["1"-"toto", "2"-"tata"])) :- % §13.14
    oro_parse_map("{1:\"toto\",2:\"tata\"}", P).
test(liboro_style, true(P == ["k"-"v", "k2"-"v 2"])) :-
    oro_parse_map("{\"k\":\"v\", \"k2\" : 'v 2'}", P).
test(first_colon_splits, true(P == ["url"-"http://x.org/a"])) :-
    oro_parse_map("{url:http://x.org/a}", P).
test(brackets_as_map, error(type_error(oro_map, "[]"))) :- % §13.14
    oro_parse_map("[]", _).
test(entry_without_colon, error(type_error(oro_map, "{a:b, c}"))) :-
    oro_parse_map("{a:b, c}", _).
test(unframed, error(type_error(oro_map, "a:b"))) :-
    oro_parse_map("a:b", _).

:- end_tests(map).


                 /*******************************
                 *          STATEMENTS          *
                 *******************************/

:- begin_tests(statements).

test(default_namespace, true(T == rdf(S, P, O))) :-
    oro_parse_statement("johnny rdf:type Human", T),
    oro(johnny, S),
    rdf_global_id(rdf:type, P),
    oro('Human', O).
test(oro_prefix, true(T == rdf(S, P, O))) :-
    oro_parse_statement("oro:Monkey rdfs:subClassOf owl:Thing", T),
    oro('Monkey', S),
    rdf_global_id(rdfs:subClassOf, P),
    rdf_global_id(owl:'Thing', O).
test(full_iris, true(T == rdf('http://x.org/a#b', 'http://x.org/p', O))) :-
    oro_parse_statement("<http://x.org/a#b> <http://x.org/p> http://x.org/a#c", T),
    O = 'http://x.org/a#c'.
test(unknown_prefix_kept, true(S == 'foo:bar')) :-
    oro_parse_statement("foo:bar p o", rdf(S, _, _)).
test(trimmed, true(T == rdf(S, P, O))) :-
    oro_parse_statement("\t johnny likes apple \r\n", T),
    oro(johnny, S),
    oro(likes, P),
    oro(apple, O).
test(atom_text, true(T == rdf(S, P, O))) :-
    oro_parse_statement('a b c', T),
    oro(a, S),
    oro(b, P),
    oro(c, O).
test(quoted_subject_is_a_name, true(S == IRI)) :-
    oro_parse_statement("'150' p o", rdf(S, _, _)),
    oro('\'150\'', IRI).
test(resource_object, true(O == IRI)) :-
    obj("Dudule", O),
    oro('Dudule', IRI).
test(quoted_object_with_spaces, true(O == L)) :-
    obj("\"Ramses the robot\"", O),
    test_literal(xsd:string, 'Ramses the robot', L).
test(variable_object, true(T = rdf(_, _, var(x)))) :-
    oro_parse_statement("johnny likes ?x", T).
test(variable_subject, true(T = rdf(var(who), _, _))) :-
    oro_parse_statement("?who rdf:type Human", T).
test(variable_predicate, true(T = rdf(_, var(p), _))) :-
    oro_parse_statement("johnny ?p apple", T).
test(all_variables, true(T == rdf(var(s), var(p), var(o)))) :-
    oro_parse_statement("?s ?p ?o", T).
test(partial, true) :-
    oro_parse_statement("?x rdf:type Human", T),
    oro_is_partial(T).
test(partial_object, true) :-
    oro_parse_statement("johnny likes ?x", T),
    oro_is_partial(T).
test(complete_not_partial, fail) :-
    oro_parse_statement("johnny likes apple", T),
    oro_is_partial(T).
test(quoted_question_mark_not_variable, fail) :-
    oro_parse_statement("johnny says \"?x\"", T),
    oro_is_partial(T).
test(is_partial_type, error(type_error(oro_triple, foo))) :-
    oro_is_partial(foo).
test(batch, true(Ts == [rdf(A, P1, B), rdf(var(x), P1, C)])) :-
    oro_parse_statements(["a p b", "?x p 'c'"], Ts),
    oro(a, A),
    oro(p, P1),
    oro(b, B),
    test_literal(xsd:string, c, C).
test(empty_batch, true(Ts == [])) :-
    oro_parse_statements([], Ts).

:- end_tests(statements).


                 /*******************************
                 *           LITERALS           *
                 *******************************/

:- begin_tests(literals).

%   The valid objects of ORO-SPEC §4.2, with the literal each gives.

valid("true",                      xsd:boolean, true).
valid("false",                     xsd:boolean, false).
valid("true^^xsd:boolean",         xsd:boolean, true).
valid("\"true\"^^xsd:boolean",     xsd:boolean, true).
valid("'true'^^xsd:boolean",       xsd:boolean, true).
valid("1^^xsd:boolean",            xsd:boolean, '1').
valid("150",                       xsd:int,     '150').
valid("\"150\"^^xsd:int",          xsd:int,     '150').
valid("150^^xsd:int",              xsd:int,     '150').
valid("\"150\"^^<http://www.w3.org/2001/XMLSchema#int>", xsd:int, '150').
valid("150^^xsd:integer",          xsd:integer, '150').
valid("150.0",                     xsd:double,  '150.0').
valid("\"150\"^^xsd:double",       xsd:double,  '150').
valid("150^^xsd:double",           xsd:double,  '150').
valid("\"150\"^^xsd:float",        xsd:float,   '150').
valid("'Dudule'",                  xsd:string,  'Dudule').
valid("\"Dudule\"",                xsd:string,  'Dudule').
valid("Dudule^^xsd:string",        xsd:string,  'Dudule').

test(spec_valid, forall(valid(Text, Type, Lex)), true(O == L)) :-
    obj(Text, O),
    test_literal(Type, Lex, L).

test(true_not_resource, true(O == L)) :-
    obj("true", O),
    test_literal(xsd:boolean, true, L).
test(true_case_sensitive, true(O == IRI)) :-
    obj("True", O),
    oro('True', IRI).
test(negative_int, true(O == L)) :-
    obj("-3", O),
    test_literal(xsd:int, '-3', L).
test(signed_int_kept, true(O == L)) :-
    obj("+007", O),
    test_literal(xsd:int, '+007', L).
test(double, true(O == L)) :-
    obj("48.5", O),
    test_literal(xsd:double, '48.5', L).
test(double_exponent, true(O == L)) :-
    obj("-3.0e2", O),
    test_literal(xsd:double, '-3.0e2', L).
test(double_leading_dot, true(O == L)) :-
    obj(".5", O),
    test_literal(xsd:double, '.5', L).
test(exponent_without_dot_is_double, true(O == L)) :-
    obj("1e5", O),
    test_literal(xsd:double, '1e5', L).
test(nan_is_resource, true(O == IRI)) :-
    obj("NaN", O),
    oro('NaN', IRI).
test(java_suffix_is_resource, true(O == IRI)) :-
    obj("1d", O),
    oro('1d', IRI).
test(single_quoted_escape, true(O == L)) :-
    obj("'it\\'s'", O),
    test_literal(xsd:string, 'it\'s', L).
test(empty_string, true(O == L)) :-
    obj("\"\"", O),
    test_literal(xsd:string, '', L).
test(separator_inside_quotes, true(O == L)) :-
    obj("\"a^^b\"", O),
    test_literal(xsd:string, 'a^^b', L).
test(last_separator, true(O == L)) :-
    obj("\"a^^b\"^^xsd:string", O),
    test_literal(xsd:string, 'a^^b', L).
test(apostrophe_in_typed, true(O == L)) :-
    obj("\"it's\"^^xsd:string", O),
    test_literal(xsd:string, 'it\'s', L).
test(angle_prefixed_type, true(O == L)) :-
    obj("150^^<xsd:int>", O),
    test_literal(xsd:int, '150', L).
test(non_xsd_type_kept, true(O == literal(type('http://x.org/t#celsius', '21')))) :-
    obj("21^^<http://x.org/t#celsius>", O).
test(oro_type_expanded, true(O == literal(type(T, '21')))) :-
    obj("21^^celsius", O),
    oro(celsius, T).
test(long, true(O == L)) :-
    obj("9000000000^^xsd:long", O),
    test_literal(xsd:long, '9000000000', L).
test(non_negative, true(O == L)) :-
    obj("0^^xsd:nonNegativeInteger", O),
    test_literal(xsd:nonNegativeInteger, '0', L).
test(decimal, true(O == L)) :-
    obj("-1.50^^xsd:decimal", O),
    test_literal(xsd:decimal, '-1.50', L).
test(decimal_integer_forms, true(Os == Ls)) :-
    maplist(obj, ["1^^xsd:decimal", "\"-1\"^^xsd:decimal", "+7^^xsd:decimal"],
            Os),
    maplist(test_literal(xsd:decimal), ['1', '-1', '+7'], Ls).
test(double_inf, true(O == L)) :-
    obj("INF^^xsd:double", O),
    test_literal(xsd:double, 'INF', L).
test(boolean_zero, true(O == L)) :-
    obj("0^^xsd:boolean", O),
    test_literal(xsd:boolean, '0', L).
test(date_time, true(O == L)) :-
    obj("2014-03-01T10:20:30.5+01:00^^xsd:dateTime", O),
    test_literal(xsd:dateTime, '2014-03-01T10:20:30.5+01:00', L).
test(date, true(O == L)) :-
    obj("\"2014-03-01\"^^xsd:date", O),
    test_literal(xsd:date, '2014-03-01', L).
test(duration, true(O == L)) :-
    obj("P1DT2H^^xsd:duration", O),
    test_literal(xsd:duration, 'P1DT2H', L).
test(any_uri, true(O == L)) :-
    obj("'http://x.org'^^xsd:anyURI", O),
    test_literal(xsd:anyURI, 'http://x.org', L).
test(lang_double_quoted, true(O == literal(lang(fr, chat)))) :-
    obj("\"chat\"@fr", O).
test(lang_single_quoted, true(O == literal(lang('en-GB', 'big cat')))) :-
    obj("'big cat'@en-GB", O).
test(at_without_quotes_is_resource, true(O == IRI)) :-
    obj("chat@fr", O),
    oro('chat@fr', IRI).

:- end_tests(literals).


                 /*******************************
                 *            ERRORS            *
                 *******************************/

:- begin_tests(errors).

test(two_tokens,
     error(syntax_error(oro_statement_tokens(2, "johnny likes")))) :-
    oro_parse_statement("johnny likes", _).
test(four_tokens,
     error(syntax_error(oro_statement_tokens(4, "a b c d")))) :-
    oro_parse_statement("a b c d", _).
test(empty_statement,
     error(syntax_error(oro_statement_tokens(1, "")))) :-
    oro_parse_statement("   ", _).
test(double_space_four_tokens,                     % [QUIRK]
     error(syntax_error(oro_statement_tokens(4, "a  b c")))) :-
    oro_parse_statement("  a  b c ", _).
test(double_space_three_tokens,
     error(syntax_error(oro_statement_empty_token("a  b")))) :-
    oro_parse_statement("a  b", _).
test(bare_question_mark,
     error(syntax_error(oro_statement_variable("? p o")))) :-
    oro_parse_statement("? p o", _).
test(true_as_int,                                  % §4.2 invalid
     error(syntax_error(oro_lexical_form("true", "xsd:int")))) :-
    obj("true^^xsd:int", _).
test(double_as_int,                                % §4.2 invalid
     error(syntax_error(oro_lexical_form("150.0", "xsd:int")))) :-
    obj("150.0^^xsd:int", _).
test(int_out_of_range,
     error(syntax_error(oro_lexical_form("300", "xsd:byte")))) :-
    obj("300^^xsd:byte", _).
test(negative_unsigned,
     error(syntax_error(oro_lexical_form("-1", "xsd:unsignedInt")))) :-
    obj("-1^^xsd:unsignedInt", _).
test(word_as_double,
     error(syntax_error(oro_lexical_form("abc", "xsd:double")))) :-
    obj("'abc'^^xsd:double", _).
test(exponent_as_decimal,
     error(syntax_error(oro_lexical_form("1e3", "xsd:decimal")))) :-
    obj("1e3^^xsd:decimal", _).
test(yes_as_boolean,
     error(syntax_error(oro_lexical_form("yes", "xsd:boolean")))) :-
    obj("yes^^xsd:boolean", _).
test(bad_date,
     error(syntax_error(oro_lexical_form("2014-13-01", "xsd:date")))) :-
    obj("2014-13-01^^xsd:date", _).
test(unknown_xsd_type,
     error(syntax_error(oro_invalid_datatype("xsd:foo")))) :-
    obj("1^^xsd:foo", _).
test(unknown_xsd_full_iri,
     error(syntax_error(oro_invalid_datatype("<http://www.w3.org/2001/XMLSchema#foo>")))) :-
    obj("1^^<http://www.w3.org/2001/XMLSchema#foo>", _).
test(empty_type,
     error(syntax_error(oro_invalid_datatype("")))) :-
    obj("1^^", _).
test(bad_unicode_in_literal,
     error(syntax_error(oro_unicode_escape(_)))) :-
    obj("\"\\u00\"", _).
test(batch_first_error,
     error(syntax_error(oro_statement_tokens(2, "b c")))) :-
    oro_parse_statements(["a p o", "b c", "d e"], _).
test(batch_not_list, error(type_error(list(text), foo))) :-
    oro_parse_statements(foo, _).
test(statement_not_text, error(type_error(text, 42))) :-
    oro_parse_statement(42, _).

%   Unterminated quotes.  The tokenizer does not split inside quotes,
%   so a quote left open swallows the rest of the text into the last
%   token; with three tokens left, that token is no name nor literal.

test(unterminated_quote_three_tokens,            % the add vector
     error(type_error(oro_statement, "a b \"unterminated, c d e"))) :-
    oro_parse_statement("a b \"unterminated, c d e", _).
test(unterminated_quote_from_set,
     error(type_error(oro_statement, "a b \"unterminated, c d e"))) :-
    oro_parse_collection(set, "[a b \"unterminated, c d e]", Elements),
    assertion(Elements == ["a b \"unterminated, c d e"]),
    oro_parse_statements(Elements, _).
test(unterminated_quote_in_batch,
     error(type_error(oro_statement, "c d \"e f"))) :-
    oro_parse_statements(["a p o", "c d \"e f", "g h i"], _).
test(trailing_double_quote,
     error(type_error(oro_statement, "s p x\""))) :-
    oro_parse_statement("s p x\"", _).
test(opening_double_quote_only,
     error(type_error(oro_statement, "s p \""))) :-
    oro_parse_statement("s p \"", _).
test(unterminated_single_quote,
     error(type_error(oro_statement, "s p 'x y"))) :-
    oro_parse_statement("s p 'x y", _).
test(apostrophe_in_object_name,
     error(type_error(oro_statement, "s p john's"))) :-
    oro_parse_statement("s p john's", _).
test(escaped_closing_quote,                      % "a\" : \" closes nothing
     error(type_error(oro_statement, "s p \"a\\\""))) :-
    oro_parse_statement("s p \"a\\\"", _).
test(unterminated_quote_trimmed,
     error(type_error(oro_statement, "s p \"x"))) :-
    oro_parse_statement("  s p \"x \t", _).
test(text_after_closing_quote,
     error(type_error(oro_statement, "s p \"abc\"def"))) :-
    obj("\"abc\"def", _).
test(single_quoted_then_text,
     error(type_error(oro_statement, "s p 'a'b"))) :-
    obj("'a'b", _).
test(empty_language_tag,
     error(type_error(oro_statement, "s p \"x\"@"))) :-
    obj("\"x\"@", _).
test(bad_language_tag,
     error(type_error(oro_statement, "s p \"x\"@1"))) :-
    obj("\"x\"@1", _).
test(unterminated_quote_atom_text,
     error(type_error(oro_statement, "s p \"x"))) :-
    oro_parse_statement('s p "x', _).
test(unterminated_quote_api,
     error(type_error(oro_statement, "s p \"x"))) :-
    oro_statements(["a p o", "s p \"x"], _, _).

:- end_tests(errors).


                 /*******************************
                 *        CLOSED QUOTES         *
                 *******************************/

/*  What the quote check accepts: every quote a token opens is closed
    in it, by a quote of the same kind, escaped quotes not counting.
*/

:- begin_tests(closed_quotes).

test(quote_of_other_kind_inside, true(O == L)) :-
    obj("'say \"hi\"'", O),
    test_literal(xsd:string, 'say "hi"', L).
test(apostrophe_inside_double_quotes, true(O == L)) :-
    obj("\"it's\"", O),
    test_literal(xsd:string, 'it\'s', L).
test(escaped_backslash_then_quote, true(O == L)) :-
    obj("\"a\\\\\"", O),
    test_literal(xsd:string, 'a\\', L).
test(escaped_quote_inside, true(O == L)) :-
    obj("\"a\\\"b\"", O),
    test_literal(xsd:string, 'a"b', L).
test(escaped_quote_in_name_kept, true(O == IRI)) :-
    obj("a\\\"b", O),
    oro('a\\"b', IRI).
test(balanced_quotes_in_name_kept, true(O == IRI)) :-  % [QUIRK] as ORO
    obj("a\"b\"c", O),
    oro('a"b"c', IRI).
test(quoted_subject_with_space_kept, true(S == IRI)) :- % [QUIRK] as ORO
    oro_parse_statement("\"a b\" p o", rdf(S, _, _)),
    oro('"a b"', IRI).
test(quoted_lang_and_type_kept, true(Os == [literal(lang(en, x)), L])) :-
    obj("\"x\"@en", O1),
    obj("'5'^^xsd:int", O2),
    Os = [O1, O2],
    test_literal(xsd:int, '5', L).
test(plain_tokens, all(T == ["a", "?x", "a\\\"b", "'q'", "\"it's\"",
                             "'\"'", "\"\"", "\"\\\\\""])) :-
    member(T, ["a", "?x", "a\\\"b", "'q'", "\"it's\"", "'\"'", "\"\"",
               "\"\\\\\""]),
    oro_parse_statement:quotes_closed(T).
test(open_tokens, all(T == ["\"", "'", "x\"", "\"a\\\"", "john's", "'a\"",
                            "\"a'\"'"])) :-
    member(T, ["\"", "'", "x\"", "\"a\\\"", "john's", "'a\"", "\"a'\"'"]),
    \+ oro_parse_statement:quotes_closed(T).

:- end_tests(closed_quotes).


                 /*******************************
                 *   FAST PATHS AGREE (PARSE)   *
                 *******************************/

/*  The parser decides plain texts with a few split_string/4 calls and
    everything else code by code (see the module doc of oro_parse).
    These tests run both paths over corpora of tricky inputs -- every
    combination of awkward tokens, and random texts over an alphabet of
    the characters that matter -- and require the same result or the
    same error.  The general paths are internal predicates, called
    module-qualified.
*/

%   outcome(:Goal, ?Result, -Outcome): Outcome is ok(Result), failed,
%   or error(Formal) for the exception Goal raised.

:- meta_predicate outcome(0, ?, -).

outcome(Goal, Result, Outcome) :-
    catch(( call(Goal)
          ->  Outcome = ok(Result)
          ;   Outcome = failed
          ),
          error(Formal, _),
          Outcome = error(Formal)).

resource_tokens([ "a", "?x", "?", "rdf:type", "oro:Monkey", "foo:bar",
                  "<http://x.org/a#b>", "<>", "<a", "a>", "http://x.org/a#b",
                  "a#b", "a<b", "_a", "1a", "caf\u00e9", "\u00e9t\u00e9",
                  "true", "12", "a^^b", "a@b", "a^b", "x:", ":x", "a'b"
                ]).

object_tokens(Tokens) :-
    resource_tokens(Resources),
    append(Resources,
           [ "false", "True", "-3", "+007", "1.5", ".5", "1.", "1e5", "1E-5",
             "-3.0e2", "1d", "NaN", "+", "-", ".", "\"q\"", "'q'", "\"\"",
             "\"x\"@en", "'x'@en-GB", "\"x\"@", "\"x\"@1", "x@en",
             "5^^xsd:int", "x^^xsd:int", "\"5\"^^xsd:int", "5^^xsd:foo",
             "5^^", "^^xsd:int", "5^^<http://x.org/t>", "5^^celsius",
             "\"it's\"^^xsd:string", "true^^xsd:boolean", "\u00e9^^xsd:int",
             "[a]", "{a}", "a\\b", "\"a\\nb\"", "\"\\u00e9\"", "\"\\u12\"",
             "\"x", "x\"", "'x", "john's", "\"a\\\"", "\"a\"b", "'a'b"
           ],
           Tokens).

statement_corpus(Text) :-
    resource_tokens(Resources),
    object_tokens(Objects),
    member(S, ["s", "?s", "rdf:type", "?", "1a", "a\"b"]),
    member(P, Resources),
    member(O, Objects),
    atomic_list_concat([S, P, O], ' ', Text0),
    (   Text = Text0
    ;   P == "a",
        member(Pre-Post, [" "-"", ""-" ", "\t"-"", ""-"\r\n"]),
        atomic_list_concat([Pre, Text0, Post], Text)
    ).
statement_corpus(Text) :-
    member(Text, [ "", " ", "a", "a b", "a b c d", "a  b c", "a b  c",
                   "  a  b c ", "a\tb c", "a b\tc", 'a b c', "a b c,d",
                   "\"a b\" p o", "s p \"a b c\"", "s p [a, b]", "s p {a b}",
                   "s p 'x y'@fr", "a\u0000 b c", "a b c\u0000"
                 ]).

%   random_text(+Alphabet, +MaxLength, -Text)

random_text(Alphabet, MaxLength, Text) :-
    random_between(0, MaxLength, Length),
    length(Codes, Length),
    string_codes(Alphabet, Pool),
    maplist(random_code(Pool), Codes),
    string_codes(Text, Codes).

random_code(Pool, Code) :-
    random_member(Code, Pool).

random_corpus(Alphabet, MaxLength, N, Texts) :-
    seeded_corpus(1234, N, random_text(Alphabet, MaxLength), Texts).

%   seeded_corpus(+Seed, +N, :Make, -Texts): N texts made by call(Make,
%   Text), the random generator seeded with Seed first, so that a corpus
%   is the same from one run to the next.

:- meta_predicate seeded_corpus(+, +, 1, -).

seeded_corpus(Seed, N, Make, Texts) :-
    set_random(seed(Seed)),
    length(Texts, N),
    maplist(Make, Texts).

statement_alphabet("ab1 ?:#<>^@\"'\\[]{},.\t-e\u00e9").

:- begin_tests(parse_fast_paths).

test(statement_corpus, Bad == []) :-
    findall(Text, statement_corpus(Text), Texts),
    statement_disagreements(Texts, Bad).
test(statement_corpus_size, true(N > 3000)) :-
    aggregate_all(count, statement_corpus(_), N).
test(statement_fast_path_taken, true) :-
    oro_parse_statement:local_statement("obj1 isOn table", _),
    oro_parse_statement:plain_statement_tokens("obj1 rdf:type Cup", _, _, _),
    \+ oro_parse_statement:local_statement("obj1 rdf:type Cup", _),
    \+ oro_parse_statement:plain_statement_tokens("obj1 p \"a\"", _, _, _),
    \+ oro_parse_statement:plain_statement_tokens(" obj1 p o", _, _, _).
test(random_statements, Bad == []) :-
    statement_alphabet(Alphabet),
    random_corpus(Alphabet, 14, 3000, Texts),
    statement_disagreements(Texts, Bad).
test(random_plain_statements, Bad == []) :-
    random_corpus("aab b1 ?:#@^\u00e9.", 12, 3000, Texts),
    statement_disagreements(Texts, Bad).
test(random_plain_statements_hit_fast_paths, true(Enough == true)) :-
    random_corpus("aab b1 ?:#@^\u00e9.", 12, 3000, Texts),
    aggregate_all(count,
                  ( member(Text, Texts),
                    local(Text)
                  ),
                  Local),
    aggregate_all(count,
                  ( member(Text, Texts),
                    \+ local(Text),
                    oro_parse_statement:plain_statement_tokens(Text, _, _, _)
                  ),
                  Plain),
    (   Local >= 5,
        Plain >= 50
    ->  Enough = true
    ;   Enough = Local-Plain
    ).
test(random_literal_statements, Bad == []) :-
    literal_corpus(3000, Texts),
    statement_disagreements(Texts, Bad).
test(random_literal_statements_hit_fast_path, true(Fast >= 300)) :-
    literal_corpus(3000, Texts),
    aggregate_all(count,
                  ( member(Text, Texts),
                    catch(oro_parse_statement:literal_statement(Text, _), error(_, _), true)
                  ),
                  Fast).
test(literal_fast_path_taken, true) :-
    oro_parse_statement:literal_statement("furniture20 rdfs:label \"table 20\"", _),
    oro_parse_statement:literal_statement("?x rdfs:label \"it's 2 m^2 @home\"", _),
    oro_parse_statement:literal_statement("a p \"\"", _),
    \+ oro_parse_statement:literal_statement("a p \"x\"@en", _),
    \+ oro_parse_statement:literal_statement("a p \"x\"^^xsd:string", _),
    \+ oro_parse_statement:literal_statement("a p \"say \\\"hi\\\"\"", _),
    \+ oro_parse_statement:literal_statement("a p \"a [b]\"", _),
    \+ oro_parse_statement:literal_statement("a p \"a\tb\"", _),
    \+ oro_parse_statement:literal_statement("a  p \"x\"", _),
    \+ oro_parse_statement:literal_statement("a p  \"x\"", _),
    \+ oro_parse_statement:literal_statement(" a p \"x\"", _),
    \+ oro_parse_statement:literal_statement("a p \"x\" ", _).
test(variables_shared_the_same, true(Ts == [rdf(X, P, O), rdf(X, P, O)])) :-
    oro_statements(["?x p ?o", "?x p ?o"], Ts, [x=X, o=O]),
    oro_parse_statement:parse_statement("a p b", rdf(_, P, _)).
test(collections_random, Bad == []) :-
    random_corpus("ab ,\"'\\[]{}\t\u0000n", 16, 3000, Inners),
    findall(Text, ( member(Inner, Inners),
                    atomics_to_string(["[", Inner, "]"], Text)
                  ), Texts),
    collection_disagreements(Texts, Bad).
test(collections_quoted_random, Bad == []) :-
    quoted_corpus(3000, Texts),
    collection_disagreements(Texts, Bad).
test(collections_quoted_escapes, true(E == ["obj1 rdfs:label \"cup\"", "b"])) :-
    oro_parse_collection(list, "[\"obj1 rdfs:label \\\"cup\\\"\", \"b\"]", E).
test(collections_quoted_random_hit_fast_path, true(Fast >= 300)) :-
    quoted_corpus(3000, Texts),
    aggregate_all(count, ( member(Text, Texts), quoted_fast(Text) ), Fast).
test(collections_quoted_fast_path_taken, true) :-
    quoted_fast("[\"obj1 rdf:type Cup\",\"obj1 isOn table1\"]"),  % liboro
    quoted_fast("[\"obj1 rdfs:label \\\"cup\\\"\",\"b\"]"),
    quoted_fast("['obj1 rdf:type Cup', 'obj1 rdfs:label \"cup\"']"), % pyoro
    quoted_fast("['it\\'s', 'b']"),
    \+ quoted_fast("[\"a\\\\\", \"b\"]"),
    \+ quoted_fast("[\"a\\\", \"b\"]"),
    quoted_fast("[ \"a\" , \"b\" ]"),
    \+ quoted_fast("[\"it's\", \"b\"]"),
    \+ quoted_fast("[\"a\",]"),
    \+ quoted_fast("[\"a\" \"b\"]"),
    \+ quoted_fast("[\"a\",\t\"b\"]").
test(collections_one_quote_random, Bad == []) :-
    one_quote_corpus(3000, Texts),
    collection_disagreements(Texts, Bad).
test(collections_one_quote_random_hit_fast_path, true(Fast >= 150)) :-
    one_quote_corpus(3000, Texts),
    aggregate_all(count, ( member(Text, Texts), one_quote_fast(Text) ), Fast).
test(collections_one_quote_fast_path_taken, true) :-
    one_quote_fast("[a rdf:type Cup, a rdfs:label \"cup 1\", b isOn a]"),
    one_quote_fast("[a rdfs:label 'cup 1' , b]"),
    one_quote_fast("[a p \"x\"\"y\", b]"),
    \+ one_quote_fast("[a rdfs:label 'cup, 1', b]"),  % a comma in a run
    \+ one_quote_fast("[\"a\", b]"),                 % opens an element
    \+ one_quote_fast("[a, \"b\"]"),
    \+ one_quote_fast("[a \"b\", \"c\"]"),
    \+ one_quote_fast("[a \"b]"),                      % never closed
    \+ one_quote_fast("[a \"b\", c 'd']").             % both quotes
test(collections_one_quote_commas_inside_runs,
     true(E == ["a rdfs:label 'cup, 1'", "b"])) :-
    oro_parse_collection(list, "[a rdfs:label 'cup, 1', b]", E).
test(set_keeps_first_occurrences, true(E == ["b", "a", "c"])) :-
    oro_parse_collection(set, "[b, a, b, c, a]", E).
test(set_without_duplicates, true(E == ["c", "a", "b"])) :-
    oro_parse_collection(set, "[c, a, b]", E).
test(clean_value_random, Bad == []) :-
    random_corpus(" a\"'\\unr0\t\u0001", 10, 3000, Texts),
    findall(Text-Fast-General,
            ( member(Text, Texts),
              outcome(oro_clean_value(Text, S1), S1, Fast),
              outcome(oro_parse_lexer:general_clean_value(Text, S2), S2, General),
              Fast \=@= General
            ),
            Bad).
test(tokenize_random, Bad == []) :-
    random_corpus("a ,\"'\\[]{}\u0000", 12, 3000, Texts),
    findall(Text-Fast-General,
            ( member(Text, Texts),
              member(D, [0',, 0'\s, 0'", 0'[, 0'\\, 0'a]),  % tracked ones too
              outcome(oro_tokenize(Text, D, T1), T1, Fast),
              outcome(oro_parse_lexer:general_tokenize(Text, D, T2), T2, General),
              Fast \=@= General
            ),
            Bad).
test(name_start, Bad == []) :-
    findall(C,
            ( between(0, 0x3000, C),
              (   oro_parse_statement:name_start(C)
              ->  Fast = true
              ;   Fast = false
              ),
              (   code_type(C, alpha),
                  \+ code_type(C, digit),
                  C \== 0'_
              ->  General = true
              ;   General = false
              ),
              Fast \== General
            ),
            Bad).
test(quotes_closed_random, Bad == []) :-
    random_corpus("a \"'\\b", 10, 3000, Texts),
    findall(Text-Fast-General,
            ( member(Text, Texts),
              test_bool(oro_parse_statement:quotes_closed(Text), Fast),
              string_codes(Text, Codes),
              test_bool(oro_parse_statement:closed_codes(Codes), General),
              Fast \== General
            ),
            Bad).
test(nul_splits_or_is_checked, true) :-
    \+ oro_parse_lexer:plain_text("a\u0000b"),
    \+ oro_parse_lexer:untracked("a\u0000b").

:- end_tests(parse_fast_paths).

local(Text) :-
    catch(oro_parse_statement:local_statement(Text, _), error(_, _), true).

%   literal_corpus(+N, -Texts): N random statements shaped as `S P
%   "literal"`, now and then with what the literal fast path must
%   refuse or leave to the general path: a quote, backslash, bracket,
%   tab or NUL inside, a suffix (`@en`, `^^type`), two spaces, a space
%   around, a variable, a prefix, an IRI in brackets.

literal_corpus(N, Texts) :-
    seeded_corpus(4321, N, literal_text, Texts).

literal_text(Text) :-
    random_member(S, ["s", "?s", "?", "obj1", "rdf:type", "<http://x/a>", "1a", "a'b"]),
    random_member(P, ["p", "rdfs:label", "?p", "a", "x:"]),
    random_member(Sep, [" ", " ", " ", " ", "  ", "\t"]),
    random_member(Alphabet, ["ab 1'^@:\u00e9", "ab 1'\"\\[]{}^@:\t\u0000\u00e9"]),
    random_text(Alphabet, 8, Inner),
    random_member(Suffix, ["", "", "", "", "@en", "^^xsd:int", " ", "x"]),
    random_member(Pre, ["", "", "", "", "", " "]),
    atomics_to_string([Pre, S, " ", P, Sep, "\"", Inner, "\"", Suffix], Text).

%   quoted_corpus(+N, -Texts): N random collections shaped as the
%   clients send them -- elements all or mostly quoted with one quote,
%   separated by a comma and spaces -- with, now and then, what the
%   fast path for quoted elements must refuse: the other quote an odd
%   number of times, a bracket, a backslash, a tab, a missing comma, a
%   bare or differently quoted element.

quoted_corpus(N, Texts) :-
    seeded_corpus(4321, N, quoted_text, Texts).

quoted_text(Text) :-
    random_member(Quote, ["\"", "'"]),
    random_between(1, 4, Count),
    length(Elements, Count),
    maplist(quoted_element(Quote), Elements),
    random_separators(Count, Separators),
    interleave(Elements, Separators, Parts),
    random_member(Pre, ["", " ", "  "]),
    random_member(Post, ["", " "]),
    atomics_to_string(["[", Pre|Parts], Text0),
    atomics_to_string([Text0, Post, "]"], Text).

quoted_element(Quote, Element) :-
    (   maybe(0.7)                          % mostly what clients send
    ->  string_concat("\\", Quote, Escaped),
        random_between(0, 6, Length),
        length(Pieces, Length),
        maplist(random_member_of(["a", "b", " ", ",", "\"", "'", Escaped]),
                Pieces),
        atomics_to_string(Pieces, Inside)
    ;   random_text("ab ,\"'\\[]{}\t", 6, Inside)
    ),
    (   maybe(0.95)
    ->  Q = Quote
    ;   random_member(Q, ["", "\"", "'"])
    ),
    atomics_to_string([Q, Inside, Q], Element).

random_member_of(List, X) :-
    random_member(X, List).

random_separators(Count, Separators) :-
    N is Count - 1,
    length(Separators, N),
    maplist(random_member_of([",", ",", ", ", " , ", ",  ", " ", ",\t",
                              ",,"]),
            Separators).

interleave([E], [], [E]).
interleave([E|Es], [S|Ss], [E, S|Parts]) :-
    interleave(Es, Ss, Parts).

%   one_quote_corpus(+N, -Texts): N collections over `a`, `b`, space,
%   comma and one quote (the same in a text), the quote more frequent.

one_quote_corpus(N, Texts) :-
    seeded_corpus(2468, N, one_quote_text, Texts).

one_quote_text(Text) :-
    random_member(Alphabet, ["ab ,\"\"", "ab ,''"]),
    random_text(Alphabet, 20, Inner),
    atomics_to_string(["[", Inner, "]"], Text).

one_quote_fast(Text) :-
    oro_parse_lexer:framed(Text, 0'[, 0'], Inner),
    oro_parse_statement:one_quote_elements(Inner, _).

quoted_fast(Text) :-
    oro_parse_lexer:framed(Text, 0'[, 0'], Inner),
    oro_parse_statement:quoted_elements(Inner, _).

%   statement_disagreements(+Texts, -Bad): Bad are Text-Fast-General
%   for each of Texts that parse_statement/2 (with its fast paths) and
%   general_statement/2 parse differently (outcome/3 of each).
%   collection_disagreements(+Texts, -Bad): the same for
%   oro_parse_collection/3 (list) and general_collection/2.

statement_disagreements(Texts, Bad) :-
    findall(Text-Fast-General,
            ( member(Text, Texts),
              outcome(oro_parse_statement:parse_statement(Text, T1), T1, Fast),
              outcome(oro_parse_statement:general_statement(Text, T2), T2, General),
              Fast \=@= General
            ),
            Bad).

collection_disagreements(Texts, Bad) :-
    findall(Text-Fast-General,
            ( member(Text, Texts),
              outcome(oro_parse_collection(list, Text, E1), E1, Fast),
              outcome(general_collection(Text, E2), E2, General),
              Fast \=@= General
            ),
            Bad).

%   general_collection(+Text, -Elements): oro_parse_collection/3 (list)
%   the general way only.

general_collection(Text, Elements) :-
    (   oro_parse_statement:null_text(Text)
    ->  Elements = []
    ;   oro_parse_lexer:framed(Text, 0'[, 0'], Inner)
    ->  (   Inner == ""
        ->  Elements = []
        ;   oro_parse_lexer:general_tokenize(Inner, 0',, Tokens),
            maplist(oro_parse_lexer:general_clean_value, Tokens, Elements)
        )
    ;   throw(error(type_error(oro_collection, Text), _))
    ).


                 /*******************************
                 *  FAST PATHS AGREE (PROTOCOL) *
                 *******************************/

/*  The same for the fast paths of prolog/oro/server/oro_protocol.pl: a block of
    bytes without `\r` cut with split_string/4, a whole short line or a
    bare `#end#` decided at once, a list of plain strings encoded in one
    piece.  Each must give what the general code gives.
*/

:- use_module(library(memfile)).
:- use_module(library(oro/server/oro_protocol)).

:- begin_tests(protocol_fast_paths).

test(block_tokens_random, Bad == []) :-
    random_corpus("ab#end\n \u00c3\u00a9", 24, 3000, Blocks),
    findall(Block-Fast-General,
            ( member(Block, Blocks),
              Block \== "",                     % fill/2 has no empty block
              split_string(Block, "\n", "", Lines),
              oro_protocol:lines_tokens(Lines, Fast),
              oro_protocol:general_block_tokens(Block, General),
              Fast \== General
            ),
            Bad).
test(line_fast_agrees, Bad-Taken == []-true) :-
    setup_call_cleanup(
        empty_octet_stream(MF, In),
        findall(Case-Fast-General,
                ( line_case(Case),
                  Case = case(Token, Max, Used0, Tokens0),
                  oro_protocol:line_fast(Token, Max, Used0, Tokens0,
                                         L1, T1, U1, S1, R1),
                  Fast = r(L1, T1, U1, S1, R1),
                  oro_protocol:line_(Token, source(In, bytes), Max,
                                     raw([], 0, ""), Used0, [], true, Tokens0,
                                     L2, T2, U2, S2, R2),
                  General = r(L2, T2, U2, S2, R2),
                  Fast \== General
                ),
                Bad),
        ( close(In), free_memory_file(MF) )),
    aggregate_all(count,
                  ( line_case(case(Token, Max, Used0, Tokens0)),
                    oro_protocol:line_fast(Token, Max, Used0, Tokens0,
                                           _, _, _, _, _)
                  ),
                  N),
    (   N > 50
    ->  Taken = true
    ;   Taken = N
    ).
test(whole_request_agrees, Bad-Taken == []-true) :-
    set_random(seed(7)),
    numlist(1, 8000, Is),
    findall(Block, ( member(_, Is), random_request_block(Block) ), Blocks),
    setup_call_cleanup(
        empty_octet_stream(MF, In),
        findall(Block-Limit-Fast-General,
                ( member(Block, Blocks),
                  member(Limit, [1000, 16]),
                  oro_protocol:whole_request(Block, Limit, Fast),
                  oro_protocol:cut_block(Block, Tokens),
                  oro_protocol:request_start(source(In, bytes), Limit, Limit,
                                             none, false, false, Tokens,
                                             Request, State),
                  General = Request-State,
                  \+ ( General = Fast-state(eol, false, [nl]) )
                ),
                Bad),
        ( close(In), free_memory_file(MF) )),
    aggregate_all(count,
                  ( member(Block, Blocks),
                    oro_protocol:whole_request(Block, 1000, _)
                  ),
                  N),
    (   N > 300
    ->  Taken = true
    ;   Taken = N
    ).
test(list_encoding_random, Bad == []) :-
    set_random(seed(99)),
    numlist(1, 2000, Is),
    findall(List-Fast-General,
            ( member(_, Is),
              random_between(0, 4, Length),
              length(List, Length),
              maplist(random_element, List),
              outcome(oro_encode_value(list(List), S1), S1, Fast),
              outcome(general_list(List, S2), S2, General),
              Fast \== General
            ),
            Bad).
test(plain_list_one_piece, true(S == "[\"a\",\"b c\",\"d\"]")) :-
    oro_encode_value(list([string(a), "b c", d]), S).
test(null_atom_not_a_string, true(S == "[\"a\",null]")) :-
    oro_encode_value(list([a, null]), S).

:- end_tests(protocol_fast_paths).

empty_octet_stream(MF, In) :-
    new_memory_file(MF),
    open_memory_file(MF, read, In, [encoding(octet)]).

%   random_request_block(-Block): a block of bytes that is often one
%   whole request and sometimes almost one.

random_request_block(Block) :-
    random_between(1, 5, N),
    length(Lines, N),
    maplist(random_request_line, Lines),
    random_member(End, ["\n#end#\n", "\n#end#\n", "\n#end#\n", "#end#\n",
                        "\n#END#\n", "\n#end#", "\n#end#\nx\n#end#\n", ""]),
    atomic_list_concat(Lines, '\n', Text),
    atomics_to_string([Text, End], Block).

random_request_line(Line) :-
    random_member(Line, [ "check", "add", "help", "HeLp \t", "", "", "[a b c]",
                          "x#end#", "#END#y", "\u00c3\u00a9t\u00c3\u00a9",
                          "\u00c3", "\u00ed\u00a0\u0080", "a\rb", "a\u0000b",
                          "  spaced ", "0123456789abcdef"
                        ]).

%   line_case(-Case): a token at the start of a line, what is known to
%   follow it, and the byte budget.

line_case(case(text(Part), Max, Used0, Tokens0)) :-
    member(Part, [ "#end#", "#END#", "a", "hello", "a#end#", "#end#b",
                   "[a b c]#end#", "x#eNd#y", "abcdef", "\u00c3\u00a9t\u00c3\u00a9",
                   "\u00e9", "\u00c3", "\u00ed\u00a0\u0080", "##end#", "#end"
                 ]),
    member(Max, [3, 4, 5, 6, 8, 1000]),
    member(Used0, [0, 2]),
    member(Tokens0, [[nl], [cr], [nl, text("x")], [text("x")], []]).

random_element(E) :-
    random_member(E, [ "a", "", "b c", "a\"b", "a\\b", "a\nb", "a\u0001",
                       "a\u0000b", "\u00e9", x, null, true, 12, 1.5,
                       string("s"), string(t), string("q\"u"), string(`co`),
                       list(["a"]), list([]), bool(true), raw("{}"), void,
                       map(["k"-"v"]), f(x), string(12)
                     ]).

%   general_list(+Elements, -String): a list encoded element by element.

general_list(Elements, String) :-
    (   oro_protocol:elements(Elements, Parts, [])
    ->  append(["["|Parts], ["]"], All),
        atomics_to_string(All, String)
    ;   type_error(oro_value, list(Elements))
    ).
